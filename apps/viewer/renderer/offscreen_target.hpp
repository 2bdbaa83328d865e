// OffscreenTarget: a multisampled colour and depth framebuffer of a given size for the capture
// mode, resolved and read back as RGB rows from the top.
#pragma once

#include "viewer/renderer/gl_object.hpp"

#include <cstdint>
#include <vector>

namespace tumble::viewer {

class OffscreenTarget {
public:
    /// Throws std::runtime_error when the framebuffer cannot be made.
    OffscreenTarget(int width, int height, int samples);

    /// Makes it the target of the next draws.
    void bind() const;
    /// Resolves the samples and returns width x height RGB pixels, the top row first.
    [[nodiscard]] std::vector<std::uint8_t> readRgb() const;

    [[nodiscard]] int width() const { return m_width; }
    [[nodiscard]] int height() const { return m_height; }

private:
    int m_width;
    int m_height;
    GlObject m_colour;
    GlObject m_depth;
    GlObject m_framebuffer;
    GlObject m_resolvedColour;
    GlObject m_resolved;
};

} // namespace tumble::viewer
