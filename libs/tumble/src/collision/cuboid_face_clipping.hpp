// Face contact between two cuboids: the incident face clipped against the reference face, and
// the reduction of the clipped points to four (docs/physics/09-box-box.md, (9.6)-(9.8)).
#pragma once

#include "collision/cuboid_features.hpp"
#include "collision/pair_manifold.hpp"

#include <array>

namespace tumble {

/// Clipping a quadrilateral by 4 planes leaves at most 8 vertices.
inline constexpr int kMaxClippedPoints = 8;

struct ClippedPoints {
    std::array<PairContactPoint, kMaxClippedPoints> points{};
    int count = 0;
};

/// The face of `box` whose outward normal is most anti-parallel to `referenceNormal` (9.6).
int incidentFaceIndex(const CuboidFrame& box, const Vec3& referenceNormal);

/// The incident face of `incident` clipped by the 4 side planes of `referenceFace` of `reference`
/// (9.7), with the points whose separation below the reference face is at most `margin`;
/// positions midway between the two surfaces, ids (9.9).
ClippedPoints clipIncidentFace(const CuboidFrame& reference, int referenceFace,
                               const CuboidFrame& incident, bool referenceIsB, Real margin);

/// At most 4 of the points, written into `manifold` with `normal`: the deepest, the farthest
/// from it, then the two that add the most area to the quadrilateral, areas measured about
/// `normal` (9.8).
void reduceContactPoints(const ClippedPoints& clipped, const Vec3& normal,
                         PairManifold& manifold);

} // namespace tumble
