// PngImage: a PNG file read with stb_image, and the pixel tests the capture tests make on it.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace tumble::viewer::testing {

class PngImage {
public:
    /// Reads `path` as 8-bit RGB; width() is 0 when the file cannot be read.
    explicit PngImage(const std::filesystem::path& path);

    [[nodiscard]] int width() const { return m_width; }
    [[nodiscard]] int height() const { return m_height; }
    /// Colour of pixel (x, y), x right and y down from the top-left corner, components 0..1.
    [[nodiscard]] glm::vec3 pixel(int x, int y) const;

    /// Number of different colours (a blank image has one).
    [[nodiscard]] std::size_t distinctColours() const;
    /// Fraction of the pixels within `radius` of `centre` (clipped to the image) that look like
    /// a cuboid face: saturated, as the face palette is and the grey ground, sky and shadow are
    /// not.
    [[nodiscard]] double cuboidFraction(const glm::vec2& centre, float radius) const;
    /// Fraction of the pixels that differ from `other`'s by more than `threshold` in a channel.
    [[nodiscard]] double differingFraction(const PngImage& other, float threshold) const;

private:
    int m_width = 0;
    int m_height = 0;
    std::vector<std::uint8_t> m_rgb;
};

/// HSV saturation of a colour: (max - min) / max, 0 for black.
float saturation(const glm::vec3& colour);

/// Saturation at or above this is a cuboid face (faces: 0.64 and more, dimmed or lit; sky 0.23 at
/// most, the ground and shadows below 0.05).
inline constexpr float kCuboidSaturation = 0.4f;

} // namespace tumble::viewer::testing
