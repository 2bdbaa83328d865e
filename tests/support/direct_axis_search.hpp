// The cuboid axis search (docs/physics/09-box-box.md, (9.1)-(9.5)) in the direct form, as a
// reference for searchContactAxis: each of the 15 axes built as a world vector and both boxes
// projected on it, 7 dot products an axis. It also notes whether any of its decisions lay
// within rounding of going the other way.
#pragma once

#include "collision/cuboid_separating_axis.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace tumble::testing {

/// Separations and normals from a few dozen double operations, relative to the box size.
inline constexpr Real kAxisRounding = 1e-12;
/// An edge axis is a cross product divided by its length, the sine: rounding of order 1e-16 in
/// its components becomes 1e-16 / sine in the axis (measured: up to 1.3e-15 / sine of the box
/// size in the separation), so below this sine the tolerance grows as 1 / sine.
inline constexpr Real kWellConditionedSine = 1e-2;

/// One axis of (9.3): s(L) = |d . L| - r_A(L) - r_B(L), r_X(L) = sum_k e_k |x_k . L| (9.1)-(9.2).
struct DirectAxis {
    ContactAxis axis;
    Real sine = 1.0;            // |a_i x b_j| of an edge pair, 1 for a face
    Real centreDistance = 0.0;  // d . L
    bool tested = true;         // false: nearly parallel edges (9.3)
};

inline Real directRadius(const CuboidFrame& box, const Vec3& axis)
{
    Real radius = 0.0;
    for (int k = 0; k < 3; ++k) {
        radius += box.halfExtents[k] * std::abs(glm::dot(box.axes[k], axis));
    }
    return radius;
}

/// The axis of `kind`: a_i, b_j or (a_i x b_j) / |a_i x b_j|.
inline DirectAxis directAxis(const CuboidFrame& a, const CuboidFrame& b, AxisKind kind, int i,
                             int j)
{
    DirectAxis result;
    Vec3 axis = kind == AxisKind::FaceA ? a.axes[i] : b.axes[j];
    if (kind == AxisKind::EdgePair) {
        const Vec3 cross = glm::cross(a.axes[i], b.axes[j]);
        result.sine = glm::length(cross);
        result.tested = result.sine >= kParallelEdgeSine;
        axis = cross / result.sine;
    }
    result.centreDistance = glm::dot(b.centre - a.centre, axis);
    const Real separation =
        std::abs(result.centreDistance) - directRadius(a, axis) - directRadius(b, axis);
    result.axis = ContactAxis{kind, kind == AxisKind::FaceB ? 0 : i,
                              kind == AxisKind::FaceA ? 0 : j,
                              result.centreDistance >= 0.0 ? axis : -axis, separation};
    return result;
}

inline DirectAxis directAxis(const CuboidFrame& a, const CuboidFrame& b, const ContactAxis& axis)
{
    return directAxis(a, b, axis.kind, axis.axisA, axis.axisB);
}

/// How far rounding may move an axis's normal.
inline Real normalTolerance(const DirectAxis& axis)
{
    return kAxisRounding * std::max(1.0, kWellConditionedSine / axis.sine);
}

/// How far rounding may move an axis's separation, m, for boxes of half extents up to `size`.
inline Real separationTolerance(const DirectAxis& axis, Real size)
{
    return size * normalTolerance(axis);
}

/// searchContactAxis's rules (9.4)-(9.5) on the direct axes.
struct DirectAxisSearch {
    const CuboidFrame& a;
    const CuboidFrame& b;
    Real margin;
    Real size;  // largest half extent of the two boxes, m
    /// No decision lay within rounding of going the other way.
    bool clearCut = true;
    /// Where rounding may put largestSeparation: the largest of the separations it is taken
    /// from, each moved down, and each moved up.
    Real largestLow = 0.0;
    Real largestHigh = 0.0;

    AxisSearch search()
    {
        std::vector<DirectAxis> tested;
        for (int k = 0; k < 3; ++k) {
            tested.push_back(directAxis(a, b, AxisKind::FaceA, k, 0));
        }
        for (int k = 0; k < 3; ++k) {
            tested.push_back(directAxis(a, b, AxisKind::FaceB, 0, k));
        }
        for (int k = 0; k < 3; ++k) {
            const bool beyondA = beyondMargin(tested[k]);
            if (beyondMargin(tested[3 + k]) || beyondA) {
                return {std::nullopt, largestOf({tested[k], tested[3 + k]})};
            }
        }
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                const DirectAxis edge = directAxis(a, b, AxisKind::EdgePair, i, j);
                note(edge.sine, kParallelEdgeSine, 1e-14);
                if (!edge.tested) {
                    continue;
                }
                if (beyondMargin(edge)) {
                    return {std::nullopt, largestOf({edge})};
                }
                tested.push_back(edge);
            }
        }
        const Real largest = largestOf(tested);
        std::optional<DirectAxis> edge;
        if (tested.size() > 6) {
            edge = tested[firstGreatest(tested, 6, tested.size())];
        }
        const std::array<DirectAxis, 6> faces{tested[0], tested[1], tested[2],
                                              tested[3], tested[4], tested[5]};
        return choose(faces, firstGreatest(tested, 0, 3), firstGreatest(tested, 3, 6), edge,
                      largest);
    }

    AxisSearch choose(const std::array<DirectAxis, 6>& faces, std::size_t faceA,
                      std::size_t faceB, const std::optional<DirectAxis>& edge, Real largest)
    {
        const Real faceTolerance = kAxisRounding * size;
        const bool faceBWins = clearlyBetter(faces[faceB].axis.separation,
                                             faces[faceA].axis.separation, 2.0 * faceTolerance);
        const DirectAxis& face = faceBWins ? faces[faceB] : faces[faceA];
        if (!edge || !clearlyBetter(edge->axis.separation, face.axis.separation,
                                    separationTolerance(*edge, size) + faceTolerance)) {
            return found(face, largest);
        }
        for (const DirectAxis& candidate : faces) {
            const Real cosine = std::abs(glm::dot(candidate.axis.normal, edge->axis.normal));
            note(cosine, kEdgeAxisFaceCosine, normalTolerance(*edge));
            if (cosine >= kEdgeAxisFaceCosine) {
                return found(candidate, largest);
            }
        }
        return found(*edge, largest);
    }

    /// Not clear-cut when lhs and rhs differ by `within` or less.
    void note(Real lhs, Real rhs, Real within)
    {
        clearCut = clearCut && std::abs(lhs - rhs) > within;
    }

    bool beyondMargin(const DirectAxis& axis)
    {
        note(axis.axis.separation, margin, separationTolerance(axis, size));
        return axis.axis.separation > margin;
    }

    /// (9.5) on the direct separations.
    bool clearlyBetter(Real candidate, Real held, Real within)
    {
        const Real bar = held + kAxisRelativeBias * std::abs(held) + kAxisAbsoluteBias;
        note(candidate, bar, within);
        return candidate > bar;
    }

    /// The first of greatest separation in [begin, end); any other within rounding of it
    /// could take its place.
    std::size_t firstGreatest(const std::vector<DirectAxis>& axes, std::size_t begin,
                              std::size_t end)
    {
        std::size_t best = begin;
        for (std::size_t k = begin + 1; k < end; ++k) {
            best = axes[k].axis.separation > axes[best].axis.separation ? k : best;
        }
        for (std::size_t k = begin; k < end; ++k) {
            if (k != best) {
                note(axes[k].axis.separation, axes[best].axis.separation,
                     separationTolerance(axes[k], size) + separationTolerance(axes[best], size));
            }
        }
        return best;
    }

    Real largestOf(const std::vector<DirectAxis>& axes)
    {
        constexpr Real kNone = -std::numeric_limits<Real>::infinity();
        Real largest = kNone;
        largestLow = kNone;
        largestHigh = kNone;
        for (const DirectAxis& axis : axes) {
            const Real within = separationTolerance(axis, size);
            largest = std::max(largest, axis.axis.separation);
            largestLow = std::max(largestLow, axis.axis.separation - within);
            largestHigh = std::max(largestHigh, axis.axis.separation + within);
        }
        return largest;
    }

    AxisSearch found(const DirectAxis& axis, Real largest)
    {
        // the normal's sign turns with d . L
        note(axis.centreDistance, 0.0, separationTolerance(axis, size));
        return {axis.axis, largest};
    }
};

} // namespace tumble::testing
