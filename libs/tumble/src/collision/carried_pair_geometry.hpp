// A pair's box-box geometry carried along with the two bodies while they move little relative to
// each other: the soft step's narrow phase between fresh searches (docs/physics/09-box-box.md,
// (9.12)).
#pragma once

#include "collision/collide_cuboid_cuboid.hpp"
#include "tumble/math.hpp"

namespace tumble {

/// (9.12): a pair's geometry is carried while no point of B has moved by more than this share of
/// the smaller box's shortest half extent relative to A since the geometry was found.
inline constexpr Real kCarryShare = 1e-4;

/// A bound on how far any point of box B (of half extents `halfExtentsB`) has moved relative to
/// A between the poses (keptA, keptB) and (poseA, poseB), m: |dc| + theta |h_B| (9.12).
Real relativeMove(const Transform& keptA, const Transform& keptB, const Transform& poseA,
                  const Transform& poseB, const Vec3& halfExtentsB);

/// The largest relative move (9.12) lets a pair of boxes of these half extents carry its geometry.
Real carryReach(const Vec3& halfExtentsA, const Vec3& halfExtentsB);

/// `found` (a geometry found at keptA, keptB) at poseA, poseB, into `carried` (not `found`):
/// each point's ends on the two surfaces moved with their bodies, the normal turned with the
/// body whose face or edge it is, the separations measured again along it (9.12). A geometry
/// whose search stopped short (separated) keeps no points. Either way the largest separation is
/// lowered by `move`, the relative move's bound, so that it stays a lower bound. Written in
/// place: a geometry holds eight points, and a pair carried every step is copied otherwise.
void carryPairGeometry(const CuboidPairGeometry& found, const Transform& keptA,
                       const Transform& keptB, const Transform& poseA, const Transform& poseB,
                       Real move, CuboidPairGeometry& carried);

} // namespace tumble
