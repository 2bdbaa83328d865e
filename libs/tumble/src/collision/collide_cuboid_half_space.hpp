// Contact of a cuboid with a half-space of any orientation (a [[plane]], or the ground as the
// island solver sees it), in the pair manifold of the box-box test (docs/physics/04-detection.md).
#pragma once

#include "collision/pair_manifold.hpp"
#include "tumble/math.hpp"
#include "tumble/shape.hpp"

namespace tumble {

/// The vertices within `margin` of the plane through `planePoint` with unit `planeNormal`, the
/// deepest four at most; the normal points out of the half-space (A = the half-space, B = the
/// cuboid) and a point's id is its vertex index (see cuboidVertices).
PairManifold collideCuboidHalfSpace(const Transform& pose, const Vec3& halfExtents,
                                    const Vec3& planePoint, const Vec3& planeNormal, Real margin);

} // namespace tumble
