// Contact between two cuboids: separating-axis test, then face clipping or the closest points of
// two edges (docs/physics/09-box-box.md).
#pragma once

#include "collision/cuboid_face_clipping.hpp"
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

/// What collideCuboids finds at two poses before the margin picks points (9.11): the largest
/// axis separation and the contact's points at every separation.
struct CuboidPairGeometry {
    /// Largest separation of the axes tested (9.2)-(9.3), m: of all of them when `complete`, else
    /// a lower bound (the first axis found beyond the search's margin).
    Real largestSeparation = 0.0;
    bool complete = false;
    /// The contact axis's normal (9.5), from A towards B, and the points of the face clipping
    /// (9.7) or the edge point (9.10), whatever their separation.
    Vec3 normal{0.0, 1.0, 0.0};
    /// Whether the normal is a face normal of B (a FaceB axis), else of A or of A's edge (9.12).
    bool normalOfB = false;
    ClippedPoints points{};
};

/// The geometry of two cuboids, its axis search stopped at the first axis separating them by
/// more than `margin` (m).
CuboidPairGeometry findCuboidPairGeometry(const CuboidFrame& a, const CuboidFrame& b,
                                          Real margin);

/// Whether `geometry` gives the manifold within `margin`: its search was complete, or it already
/// found an axis separating the boxes by more than `margin`.
bool decidesMargin(const CuboidPairGeometry& geometry, Real margin);

/// The manifold of collideCuboids within `margin`, from a geometry that decides it: no points if
/// the largest separation exceeds `margin`, else the points within it reduced to four (9.8).
PairManifold manifoldWithin(const CuboidPairGeometry& geometry, Real margin);

/// manifoldWithin written into `manifold`, whose normal is left as it was when no point is
/// within `margin` (a narrow phase's manifolds are read only where they have points).
void writeManifoldWithin(const CuboidPairGeometry& geometry, Real margin,
                         PairManifold& manifold);

} // namespace tumble
