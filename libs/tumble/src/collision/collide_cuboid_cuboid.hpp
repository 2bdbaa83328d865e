// Contact between two cuboids: separating-axis test, then face clipping or the closest points of
// two edges (docs/physics/09-box-box.md).
#pragma once

#include "collision/pair_manifold.hpp"
#include "tumble/math.hpp"

namespace tumble {

/// The contact of cuboid A with cuboid B, a pure function of the poses. No points if the boxes
/// are separated by more than `margin` (m) along one of the 15 axes (9.2)-(9.3); otherwise up to
/// 4 points with separation <= margin (speculative when positive), on the axis chosen by (9.5):
/// a reference face clipped against the other box's incident face (9.6)-(9.8), or one point
/// between two crossing edges (9.10). The normal points from A towards B.
PairManifold collideCuboids(const Transform& poseA, const Vec3& halfExtentsA,
                            const Transform& poseB, const Vec3& halfExtentsB, Real margin);

} // namespace tumble
