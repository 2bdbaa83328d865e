// OrbitCamera: orbit, zoom, pan and follow around a target point, the view and projection
// matrices, and where a world point lands on the screen. Pure math (glm), no GL.
#pragma once

#include <glm/glm.hpp>

#include <optional>
#include <span>

namespace tumble::viewer {

/// A sphere that should be in view: the bodies of a scene, and the ground under them.
struct ViewBounds {
    glm::vec3 centre{0.0f};
    float radius = 1.0f;
};

/// A rectangle of the window, pixels (x right, y down from the top-left corner): the part the
/// panels leave to the 3D view.
struct ViewRegion {
    glm::vec2 min{0.0f};
    glm::vec2 max{0.0f};

    [[nodiscard]] glm::vec2 centre() const { return 0.5f * (min + max); }
    [[nodiscard]] glm::vec2 size() const { return max - min; }
};

/// The whole of a view of this size.
inline ViewRegion wholeView(const glm::ivec2& size) { return {glm::vec2(0.0f), glm::vec2(size)}; }

/// A camera on a sphere around a target point: yaw about the vertical, pitch above the horizon,
/// distance from the target. y is up, as in the simulation.
class OrbitCamera {
public:
    /// Vertical field of view, rad (45 degrees).
    static constexpr float kFieldOfViewY = 0.78539816f;
    /// Pitch limits, rad: a little below the horizon up to nearly straight down.
    static constexpr float kMinPitch = -0.2f;
    static constexpr float kMaxPitch = 1.5f;
    /// Distance limits, m.
    static constexpr float kMinDistance = 0.5f;
    static constexpr float kMaxDistance = 2000.0f;
    /// Orbit rate, rad per pixel dragged.
    static constexpr float kOrbitRate = 0.006f;
    /// Each wheel step moves this fraction of the distance towards the target.
    static constexpr float kZoomStep = 0.1f;
    /// Follow stiffness, 1/s: the target closes 1 - exp(-k t) of the gap in t seconds.
    static constexpr float kFollowRate = 8.0f;
    /// The default view direction: 35 degrees round from +z towards +x, 22 degrees above.
    static constexpr float kDefaultYaw = 0.61f;
    static constexpr float kDefaultPitch = 0.38f;

    OrbitCamera() = default;
    OrbitCamera(const glm::vec3& target, float distance, float yaw = kDefaultYaw,
                float pitch = kDefaultPitch);

    /// Rotates about the target for a mouse drag of (dx, dy) pixels (right, down).
    void orbit(float dxPixels, float dyPixels);
    /// Moves towards the target by kZoomStep of the distance per wheel step (negative: away).
    void zoom(float wheelSteps);
    /// Moves the target in the view plane so that a point at the target's depth follows a drag
    /// of (dx, dy) pixels in a viewport `viewportHeight` pixels high.
    void pan(float dxPixels, float dyPixels, float viewportHeight);
    /// Eases the target towards `point` over `seconds` of real time (kFollowRate).
    void follow(const glm::vec3& point, float seconds);

    [[nodiscard]] const glm::vec3& target() const { return m_target; }
    [[nodiscard]] float distance() const { return m_distance; }
    [[nodiscard]] float yaw() const { return m_yaw; }
    [[nodiscard]] float pitch() const { return m_pitch; }

    /// Camera position, world frame.
    [[nodiscard]] glm::vec3 eye() const;
    /// Unit vectors: from the eye towards the target, to the right of the view, up in the view.
    [[nodiscard]] glm::vec3 forward() const;
    [[nodiscard]] glm::vec3 right() const;
    [[nodiscard]] glm::vec3 up() const;

    [[nodiscard]] glm::mat4 view() const;
    /// Perspective projection for a viewport of this width / height; near and far planes scale
    /// with the distance.
    [[nodiscard]] glm::mat4 projection(float aspect) const;
    /// Pixel position of a world point in a width x height image (x right, y down, origin at
    /// the top-left corner, pixel centres at .5) in x and y; z is the depth in front of the
    /// camera, m (not positive: behind it, and x, y mean nothing).
    [[nodiscard]] glm::vec3 projectToPixel(const glm::vec3& world, int width, int height) const;

private:
    glm::vec3 m_target{0.0f};
    float m_distance = 10.0f;
    float m_yaw = kDefaultYaw;
    float m_pitch = kDefaultPitch;
};

/// The smallest sphere (about the centre of the boxes' bounds) holding spheres at `centres`
/// with `radii`; with a ground height, the ground point under the lowest sphere is held too.
ViewBounds boundsOf(std::span<const glm::vec3> centres, std::span<const float> radii,
                    std::optional<float> groundHeight);

/// A camera in the default direction that sees the whole of `bounds`, with a margin, in a view
/// of this aspect (width / height).
OrbitCamera frameBounds(const ViewBounds& bounds, float aspect);

} // namespace tumble::viewer
