#include "viewer/picking.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble::viewer {

Ray pixelRay(const OrbitCamera& camera, const glm::vec2& pixel, const glm::vec2& size)
{
    // normalised device coordinates, y up, then back through the inverse view-projection
    const glm::vec2 ndc(2.0f * pixel.x / size.x - 1.0f, 1.0f - 2.0f * pixel.y / size.y);
    const glm::mat4 inverse = glm::inverse(camera.projection(size.x / size.y) * camera.view());
    const glm::vec4 near = inverse * glm::vec4(ndc, -1.0f, 1.0f);
    const glm::vec4 far = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 from = glm::vec3(near) / near.w;
    const glm::vec3 to = glm::vec3(far) / far.w;
    return Ray{camera.eye(), glm::normalize(to - from)};
}

std::optional<float> rayHitsCuboid(const Ray& ray, const Body& body)
{
    // into the body frame, where the cuboid is the box |x_k| <= h_k
    const glm::quat toBody = glm::conjugate(glm::quat(body.orientation));
    const glm::vec3 origin = toBody * (ray.origin - glm::vec3(body.position));
    const glm::vec3 direction = toBody * ray.direction;
    const glm::vec3 half(body.shape.halfExtents());
    float enter = -std::numeric_limits<float>::infinity();
    float leave = std::numeric_limits<float>::infinity();
    for (int k = 0; k < 3; ++k) {
        if (std::abs(direction[k]) < 1e-12f) {
            if (std::abs(origin[k]) > half[k]) {
                return std::nullopt;
            }
            continue;
        }
        const float a = (-half[k] - origin[k]) / direction[k];
        const float b = (half[k] - origin[k]) / direction[k];
        enter = std::max(enter, std::min(a, b));
        leave = std::min(leave, std::max(a, b));
    }
    if (enter > leave || leave < 0.0f) {
        return std::nullopt;
    }
    return std::max(enter, 0.0f);
}

std::optional<std::size_t> pickBody(const Ray& ray, const World& world,
                                    std::span<const BodyId> bodies)
{
    std::optional<std::size_t> nearest;
    float nearestDistance = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const Body& body = world.body(bodies[i]);
        if (body.isStatic()) {
            continue;
        }
        const std::optional<float> distance = rayHitsCuboid(ray, body);
        if (distance && *distance < nearestDistance) {
            nearestDistance = *distance;
            nearest = i;
        }
    }
    return nearest;
}

} // namespace tumble::viewer
