#include "png_image.hpp"

#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <unordered_set>

namespace tumble::viewer::testing {

PngImage::PngImage(const std::filesystem::path& path)
{
    int channels = 0;
    unsigned char* data = stbi_load(path.string().c_str(), &m_width, &m_height, &channels, 3);
    if (data == nullptr) {
        m_width = 0;
        m_height = 0;
        return;
    }
    m_rgb.assign(data, data + static_cast<std::size_t>(m_width) * static_cast<std::size_t>(m_height) * 3);
    stbi_image_free(data);
}

glm::vec3 PngImage::pixel(int x, int y) const
{
    const std::size_t at = (static_cast<std::size_t>(y) * static_cast<std::size_t>(m_width) +
                            static_cast<std::size_t>(x)) *
                           3;
    return glm::vec3(m_rgb[at], m_rgb[at + 1], m_rgb[at + 2]) / 255.0f;
}

std::size_t PngImage::distinctColours() const
{
    std::unordered_set<std::uint32_t> colours;
    for (std::size_t i = 0; i + 2 < m_rgb.size(); i += 3) {
        colours.insert(static_cast<std::uint32_t>(m_rgb[i]) << 16 |
                       static_cast<std::uint32_t>(m_rgb[i + 1]) << 8 | m_rgb[i + 2]);
    }
    return colours.size();
}

double PngImage::cuboidFraction(const glm::vec2& centre, float radius) const
{
    int inside = 0;
    int cuboid = 0;
    const int r = static_cast<int>(std::ceil(radius));
    for (int y = static_cast<int>(centre.y) - r; y <= static_cast<int>(centre.y) + r; ++y) {
        for (int x = static_cast<int>(centre.x) - r; x <= static_cast<int>(centre.x) + r; ++x) {
            if (x < 0 || y < 0 || x >= m_width || y >= m_height ||
                glm::length(glm::vec2(x, y) + 0.5f - centre) > radius) {
                continue;
            }
            ++inside;
            cuboid += saturation(pixel(x, y)) >= kCuboidSaturation ? 1 : 0;
        }
    }
    return inside == 0 ? 0.0 : static_cast<double>(cuboid) / inside;
}

double PngImage::differingFraction(const PngImage& other, float threshold) const
{
    if (other.m_width != m_width || other.m_height != m_height || m_rgb.empty()) {
        return 1.0;
    }
    std::size_t differing = 0;
    for (std::size_t i = 0; i + 2 < m_rgb.size(); i += 3) {
        bool differs = false;
        for (std::size_t c = 0; c < 3; ++c) {
            differs |= std::abs(m_rgb[i + c] - other.m_rgb[i + c]) > threshold * 255.0f;
        }
        differing += differs ? 1 : 0;
    }
    return static_cast<double>(differing) / static_cast<double>(m_rgb.size() / 3);
}

float saturation(const glm::vec3& colour)
{
    const float high = std::max({colour.r, colour.g, colour.b});
    const float low = std::min({colour.r, colour.g, colour.b});
    return high <= 0.0f ? 0.0f : (high - low) / high;
}

} // namespace tumble::viewer::testing
