#include "viewer/ground_shadow.hpp"

#include <algorithm>

namespace tumble::viewer {
namespace {

float cross(const glm::vec2& origin, const glm::vec2& a, const glm::vec2& b)
{
    return (a.x - origin.x) * (b.y - origin.y) - (a.y - origin.y) * (b.x - origin.x);
}

} // namespace

std::vector<glm::vec2> convexHull(std::vector<glm::vec2> points)
{
    std::sort(points.begin(), points.end(), [](const glm::vec2& a, const glm::vec2& b) {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3) {
        return points;
    }
    // lower hull left to right, then upper hull right to left, keeping left turns only
    std::vector<glm::vec2> hull(2 * points.size());
    std::size_t count = 0;
    for (const glm::vec2& point : points) {
        while (count >= 2 && cross(hull[count - 2], hull[count - 1], point) <= 0.0f) {
            --count;
        }
        hull[count++] = point;
    }
    const std::size_t lowerCount = count + 1;
    for (auto it = points.rbegin() + 1; it != points.rend(); ++it) {
        while (count >= lowerCount && cross(hull[count - 2], hull[count - 1], *it) <= 0.0f) {
            --count;
        }
        hull[count++] = *it;
    }
    // the last point repeats the first
    hull.resize(count - 1);
    return hull;
}

std::vector<glm::vec2> groundShadow(const glm::mat4& model, const glm::vec3& towardsLight,
                                    float groundHeight)
{
    std::vector<glm::vec2> projected;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec4 local((corner & 1) ? 0.5f : -0.5f, (corner & 2) ? 0.5f : -0.5f,
                              (corner & 4) ? 0.5f : -0.5f, 1.0f);
        const glm::vec3 world(model * local);
        // slide along the light ray down to the plane
        const float along = (world.y - groundHeight) / towardsLight.y;
        const glm::vec3 onGround = world - towardsLight * along;
        projected.emplace_back(onGround.x, onGround.z);
    }
    return convexHull(std::move(projected));
}

} // namespace tumble::viewer
