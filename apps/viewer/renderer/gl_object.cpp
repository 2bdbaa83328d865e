#include "viewer/renderer/gl_object.hpp"

#include <stdexcept>
#include <utility>

namespace tumble::viewer {

GlObject GlObject::create(GlKind kind)
{
    GLuint name = 0;
    switch (kind) {
    case GlKind::Buffer:
        glGenBuffers(1, &name);
        break;
    case GlKind::VertexArray:
        glGenVertexArrays(1, &name);
        break;
    case GlKind::Texture:
        glGenTextures(1, &name);
        break;
    case GlKind::Framebuffer:
        glGenFramebuffers(1, &name);
        break;
    case GlKind::Renderbuffer:
        glGenRenderbuffers(1, &name);
        break;
    case GlKind::Shader:
    case GlKind::Program:
        throw std::logic_error("GlObject::create: shaders and programs need glCreateShader");
    }
    return GlObject(kind, name);
}

GlObject& GlObject::operator=(GlObject&& other) noexcept
{
    if (this != &other) {
        release();
        m_kind = other.m_kind;
        m_name = std::exchange(other.m_name, 0);
    }
    return *this;
}

void GlObject::release()
{
    if (m_name == 0) {
        return;
    }
    switch (m_kind) {
    case GlKind::Buffer:
        glDeleteBuffers(1, &m_name);
        break;
    case GlKind::VertexArray:
        glDeleteVertexArrays(1, &m_name);
        break;
    case GlKind::Texture:
        glDeleteTextures(1, &m_name);
        break;
    case GlKind::Framebuffer:
        glDeleteFramebuffers(1, &m_name);
        break;
    case GlKind::Renderbuffer:
        glDeleteRenderbuffers(1, &m_name);
        break;
    case GlKind::Shader:
        glDeleteShader(m_name);
        break;
    case GlKind::Program:
        glDeleteProgram(m_name);
        break;
    }
    m_name = 0;
}

} // namespace tumble::viewer
