#include "viewer/renderer/offscreen_target.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace tumble::viewer {
namespace {

void checkComplete(const char* what)
{
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw std::runtime_error(std::string("the capture framebuffer (") + what +
                                 ") is incomplete");
    }
}

} // namespace

OffscreenTarget::OffscreenTarget(int width, int height, int samples)
    : m_width(width), m_height(height), m_colour(GlObject::create(GlKind::Renderbuffer)),
      m_depth(GlObject::create(GlKind::Renderbuffer)),
      m_framebuffer(GlObject::create(GlKind::Framebuffer)),
      m_resolvedColour(GlObject::create(GlKind::Renderbuffer)),
      m_resolved(GlObject::create(GlKind::Framebuffer))
{
    // multisampled colour and depth-stencil, drawn into
    glBindRenderbuffer(GL_RENDERBUFFER, m_colour.name());
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, m_depth.name());
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH24_STENCIL8, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.name());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m_colour.name());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              m_depth.name());
    checkComplete("multisampled");

    // single-sampled colour, resolved into and read back
    glBindRenderbuffer(GL_RENDERBUFFER, m_resolvedColour.name());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, m_resolved.name());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                              m_resolvedColour.name());
    checkComplete("resolved");
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void OffscreenTarget::bind() const
{
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.name());
    glViewport(0, 0, m_width, m_height);
}

std::vector<std::uint8_t> OffscreenTarget::readRgb() const
{
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_framebuffer.name());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, m_resolved.name());
    glBlitFramebuffer(0, 0, m_width, m_height, 0, 0, m_width, m_height, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);

    const auto rowBytes = static_cast<std::size_t>(m_width) * 3;
    std::vector<std::uint8_t> bottomUp(rowBytes * static_cast<std::size_t>(m_height));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m_resolved.name());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, m_width, m_height, GL_RGB, GL_UNSIGNED_BYTE, bottomUp.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    // GL's rows start at the bottom, image files' at the top
    std::vector<std::uint8_t> topDown(bottomUp.size());
    for (int row = 0; row < m_height; ++row) {
        const auto from = static_cast<std::size_t>(m_height - 1 - row) * rowBytes;
        const auto to = static_cast<std::size_t>(row) * rowBytes;
        std::copy_n(bottomUp.begin() + static_cast<std::ptrdiff_t>(from), rowBytes,
                    topDown.begin() + static_cast<std::ptrdiff_t>(to));
    }
    return topDown;
}

} // namespace tumble::viewer
