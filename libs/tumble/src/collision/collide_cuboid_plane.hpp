// Which vertices of a cuboid touch or penetrate a horizontal plane (docs/physics/04-detection.md).
#pragma once

#include "tumble/contact.hpp"
#include "tumble/math.hpp"
#include "tumble/shape.hpp"

namespace tumble {

/// Height of each cuboid vertex above the plane, m (negative: below it), for the body pose.
std::array<Real, 8> vertexHeights(const Transform& pose, const Vec3& halfExtents, const Plane& plane);

/// The vertices with height <= tolerance, in vertex-index order, with their world coordinates
/// and penetration (4.1)-(4.2). Impulses in the points are zero.
ContactManifold collideCuboidPlane(const Transform& pose, const Vec3& halfExtents,
                                   const Plane& plane, Real tolerance);

/// Height of the lowest vertex above the plane, m (4.1).
Real lowestVertexHeight(const Transform& pose, const Vec3& halfExtents, const Plane& plane);

} // namespace tumble
