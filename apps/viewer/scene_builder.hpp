// What the renderer draws, as plain data built from the World's public state: a transform per
// cuboid, arrows (impulses, axes, angular velocity and momentum), contact markers, the ground.
// Pure: no GL, so it is tested without a window.
#pragma once

#include "viewer/viewer_settings.hpp"

#include "tumble/body_id.hpp"
#include "tumble/contact.hpp"
#include "tumble/world.hpp"

#include <glm/glm.hpp>

#include <optional>
#include <span>
#include <vector>

namespace tumble::viewer {

struct CuboidInstance {
    /// Takes the unit cube of cuboidMesh() to the body: translate, rotate, scale by the size.
    glm::mat4 model{1.0f};
    /// For normals: the inverse transpose of model's upper 3x3.
    glm::mat3 normalMatrix{1.0f};
    glm::vec3 centre{0.0f};
    /// Radius of the bounding sphere, m.
    float radius = 0.0f;
    bool selected = false;
    /// Static geometry (a static body, a patch of a plane): drawn dimmed.
    bool fixed = false;
};

struct ArrowInstance {
    glm::vec3 from{0.0f};
    glm::vec3 to{0.0f};
    glm::vec3 colour{1.0f};
    /// Shaft radius, m.
    float radius = 0.05f;
    /// Drawn over the bodies (the collision impulses, which start under the body).
    bool onTop = false;
};

struct MarkerInstance {
    glm::vec3 position{0.0f};
    glm::vec3 colour{1.0f};
    /// Diameter on screen, pixels.
    float sizePixels = 10.0f;
};

struct SceneDrawList {
    std::vector<CuboidInstance> cuboids;
    std::vector<ArrowInstance> arrows;
    std::vector<MarkerInstance> markers;
    /// Height of the grid plane, m.
    float gridHeight = 0.0f;
    /// True for the scenario's ground; false for a reference grid under a scene without one.
    bool gridIsGround = true;
};

/// Arrows shorter than this are left out, m.
inline constexpr float kMinArrowLength = 1e-3f;
/// Half the side of the square patch drawn for a plane beyond the farthest body from its point,
/// and its thickness, m.
inline constexpr float kPlanePatchMargin = 2.0f;
inline constexpr float kPlanePatchThickness = 0.01f;
/// Marker sizes, pixels.
inline constexpr float kVertexMarkerPixels = 11.0f;
inline constexpr float kAverageMarkerPixels = 16.0f;

/// The contact markers' size factor for a scene of this many bodies: 1 up to ten bodies, then
/// shrinking as 1/sqrt(n) (with a hundred bodies the full-size dots hid the cuboids), never
/// below kMinMarkerScale.
inline constexpr float kMinMarkerScale = 0.35f;
float contactMarkerScale(std::size_t bodyCount);

/// The draw list for `bodies` of `world`. `lastCollisions` is indexed like `bodies`;
/// `referenceHeight` places the grid when the world has no ground.
SceneDrawList buildScene(const World& world, std::span<const BodyId> bodies,
                         std::span<const std::optional<CollisionEvent>> lastCollisions,
                         const ViewerSettings& settings, float referenceHeight);

} // namespace tumble::viewer
