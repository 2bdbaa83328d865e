#include "viewer/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace tumble::viewer {
namespace {

/// Extra room around framed bounds, as a fraction of their radius.
constexpr float kFrameMargin = 0.2f;

} // namespace

OrbitCamera::OrbitCamera(const glm::vec3& target, float distance, float yaw, float pitch)
    : m_target(target), m_distance(std::clamp(distance, kMinDistance, kMaxDistance)), m_yaw(yaw),
      m_pitch(std::clamp(pitch, kMinPitch, kMaxPitch))
{
}

void OrbitCamera::orbit(float dxPixels, float dyPixels)
{
    // dragging right turns the scene right, dragging down looks from higher up
    m_yaw -= dxPixels * kOrbitRate;
    m_pitch = std::clamp(m_pitch + dyPixels * kOrbitRate, kMinPitch, kMaxPitch);
}

void OrbitCamera::zoom(float wheelSteps)
{
    const float factor = std::pow(1.0f - kZoomStep, wheelSteps);
    m_distance = std::clamp(m_distance * factor, kMinDistance, kMaxDistance);
}

void OrbitCamera::pan(float dxPixels, float dyPixels, float viewportHeight)
{
    // metres per pixel at the target's depth: the view's height there is 2 d tan(fov / 2)
    const float metresPerPixel =
        2.0f * m_distance * std::tan(0.5f * kFieldOfViewY) / std::max(viewportHeight, 1.0f);
    m_target += (-dxPixels * right() + dyPixels * up()) * metresPerPixel;
}

void OrbitCamera::follow(const glm::vec3& point, float seconds)
{
    const float closed = 1.0f - std::exp(-kFollowRate * std::max(seconds, 0.0f));
    m_target += (point - m_target) * closed;
}

glm::vec3 OrbitCamera::eye() const
{
    const glm::vec3 offset(std::cos(m_pitch) * std::sin(m_yaw), std::sin(m_pitch),
                           std::cos(m_pitch) * std::cos(m_yaw));
    return m_target + m_distance * offset;
}

glm::vec3 OrbitCamera::forward() const { return glm::normalize(m_target - eye()); }

glm::vec3 OrbitCamera::right() const
{
    // the horizontal direction to the right of the view (well defined: |pitch| < 90 degrees)
    return glm::vec3(std::cos(m_yaw), 0.0f, -std::sin(m_yaw));
}

glm::vec3 OrbitCamera::up() const { return glm::cross(right(), forward()); }

glm::mat4 OrbitCamera::view() const { return glm::lookAt(eye(), m_target, up()); }

glm::mat4 OrbitCamera::projection(float aspect) const
{
    const float nearPlane = std::clamp(0.01f * m_distance, 0.02f, 2.0f);
    const float farPlane = 20.0f * m_distance + 300.0f;
    return glm::perspective(kFieldOfViewY, std::max(aspect, 1e-3f), nearPlane, farPlane);
}

glm::vec3 OrbitCamera::projectToPixel(const glm::vec3& world, int width, int height) const
{
    const float aspect = static_cast<float>(width) / static_cast<float>(std::max(height, 1));
    const glm::vec4 clip = projection(aspect) * view() * glm::vec4(world, 1.0f);
    const float depth = clip.w;
    if (depth <= 0.0f) {
        return {0.0f, 0.0f, depth};
    }
    // normalised device coordinates (y up) to pixels (y down)
    const glm::vec2 ndc(clip.x / clip.w, clip.y / clip.w);
    return {0.5f * (ndc.x + 1.0f) * static_cast<float>(width),
            0.5f * (1.0f - ndc.y) * static_cast<float>(height), depth};
}

ViewBounds boundsOf(std::span<const glm::vec3> centres, std::span<const float> radii,
                    std::optional<float> groundHeight)
{
    if (centres.empty()) {
        return {};
    }
    // what must be seen: each sphere, and the ground point under it
    std::vector<glm::vec3> points(centres.begin(), centres.end());
    std::vector<float> pointRadii;
    for (std::size_t i = 0; i < centres.size(); ++i) {
        pointRadii.push_back(i < radii.size() ? radii[i] : 0.0f);
    }
    if (groundHeight) {
        for (const glm::vec3& centre : centres) {
            points.emplace_back(centre.x, *groundHeight, centre.z);
            pointRadii.push_back(0.0f);
        }
    }

    // centre of their bounding box, then the radius that holds every sphere about it
    glm::vec3 low(points[0] - pointRadii[0]);
    glm::vec3 high(points[0] + pointRadii[0]);
    for (std::size_t i = 1; i < points.size(); ++i) {
        low = glm::min(low, points[i] - pointRadii[i]);
        high = glm::max(high, points[i] + pointRadii[i]);
    }
    ViewBounds bounds{.centre = 0.5f * (low + high), .radius = 0.0f};
    for (std::size_t i = 0; i < points.size(); ++i) {
        bounds.radius =
            std::max(bounds.radius, glm::length(points[i] - bounds.centre) + pointRadii[i]);
    }
    bounds.radius = std::max(bounds.radius, 0.5f);
    return bounds;
}

OrbitCamera frameBounds(const ViewBounds& bounds, float aspect)
{
    // the sphere fits when its radius subtends at most half the narrower field of view
    const float halfVertical = 0.5f * OrbitCamera::kFieldOfViewY;
    const float halfHorizontal = std::atan(std::tan(halfVertical) * std::max(aspect, 1e-3f));
    const float halfAngle = std::min(halfVertical, halfHorizontal);
    return OrbitCamera(bounds.centre, bounds.radius * (1.0f + kFrameMargin) / std::sin(halfAngle));
}

} // namespace tumble::viewer
