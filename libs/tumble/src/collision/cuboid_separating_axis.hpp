// The separating-axis test between two cuboids and the choice of the contact axis
// (docs/physics/09-box-box.md, (9.1)-(9.5)).
#pragma once

#include "collision/cuboid_features.hpp"

#include <cstdint>
#include <optional>

namespace tumble {

/// An edge cross product shorter than this (the sine of the angle between the edges) is not
/// tested: its direction is rounding noise, and the face axes cover nearly parallel edges (9.3).
inline constexpr Real kParallelEdgeSine = 1e-6;
/// A later candidate axis replaces the one held only if its separation is larger by
/// kAxisRelativeBias |held| + kAxisAbsoluteBias (9.5): faces of A first, then faces of B, then
/// edge pairs.
inline constexpr Real kAxisRelativeBias = 1e-3;
inline constexpr Real kAxisAbsoluteBias = 1e-5;  // m
/// An edge axis that wins but lies within about 5.7 degrees of a face normal (|cos| above this)
/// gives way to that face (9.5): a nearly parallel face-face contact overhanging an edge must
/// keep its face manifold, not collapse to one edge point.
inline constexpr Real kEdgeAxisFaceCosine = 0.995;

enum class AxisKind : std::uint8_t { FaceA, FaceB, EdgePair };

/// The axis a contact is built on.
struct ContactAxis {
    AxisKind kind = AxisKind::FaceA;
    int axisA = 0;  // axis of A (FaceA, EdgePair), 0..2
    int axisB = 0;  // axis of B (FaceB, EdgePair), 0..2
    Vec3 normal{0.0, 1.0, 0.0};  // unit, from A towards B
    Real separation = 0.0;       // m, (9.2); negative: overlap along this axis
};

/// Half the length of the box's projection on the unit axis (9.1).
Real projectedRadius(const CuboidFrame& box, const Vec3& axis);

/// What the search of the 15 axes found.
struct AxisSearch {
    /// The contact axis; empty if some axis separates the boxes by more than the margin.
    std::optional<ContactAxis> axis;
    /// Largest separation (9.2) of the axes tested, m. With an axis found it is that of all
    /// tested axes, the value compared with the margin; without one, that of the first axis
    /// beyond the margin, so a lower bound.
    Real largestSeparation = 0.0;
};

/// Tests the 15 axes (9.2)-(9.3). No axis if some axis separates the boxes by more than
/// `margin`; otherwise the axis of greatest separation (minus the penetration depth (9.4)),
/// biased towards faces and towards A, with edge axes nearly along a face normal replaced by
/// that face (9.5).
AxisSearch searchContactAxis(const CuboidFrame& a, const CuboidFrame& b, Real margin);

/// The axis of searchContactAxis alone.
std::optional<ContactAxis> findContactAxis(const CuboidFrame& a, const CuboidFrame& b,
                                           Real margin);

} // namespace tumble
