// Choosing a body with the mouse: the ray through a pixel of the 3D view and the nearest body it
// enters. Pure: no GL, tested without a window.
#pragma once

#include "viewer/camera.hpp"

#include "tumble/body_id.hpp"
#include "tumble/world.hpp"

#include <glm/glm.hpp>

#include <optional>
#include <span>

namespace tumble::viewer {

struct Ray {
    glm::vec3 origin{0.0f};
    /// Unit length.
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
};

/// The ray from the eye through `pixel` (from the view's top-left corner) of a view `size` pixels.
Ray pixelRay(const OrbitCamera& camera, const glm::vec2& pixel, const glm::vec2& size);

/// Distance along the ray to where it enters the body's cuboid (slab test in the body frame), or
/// none when it misses or the cuboid is behind the origin.
std::optional<float> rayHitsCuboid(const Ray& ray, const Body& body);

/// Index in `bodies` of the nearest moving body the ray enters; static geometry is not picked.
std::optional<std::size_t> pickBody(const Ray& ray, const World& world,
                                    std::span<const BodyId> bodies);

} // namespace tumble::viewer
