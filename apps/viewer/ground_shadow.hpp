// The shadow a cuboid casts on the ground under a directional light, as a convex polygon: the
// renderer shades it with a soft edge. Pure geometry (glm), unit-tested.
#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace tumble::viewer {

/// The convex hull, in ground coordinates (x, z), of the corners of the cuboid `model` (which
/// takes the unit cube [-0.5, 0.5]^3 to the body) projected along `towardsLight` (pointing up,
/// y > 0) onto the plane y = groundHeight; counter-clockwise for the cross product
/// a.x b.y - a.y b.x of (x, z) pairs, with no repeated point.
std::vector<glm::vec2> groundShadow(const glm::mat4& model, const glm::vec3& towardsLight,
                                    float groundHeight);

/// Andrew's monotone chain: the convex hull of `points`, counter-clockwise, collinear points
/// dropped.
std::vector<glm::vec2> convexHull(std::vector<glm::vec2> points);

} // namespace tumble::viewer
