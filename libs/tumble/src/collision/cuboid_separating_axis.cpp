// Separating-axis test between two cuboids (docs/physics/09-box-box.md, (9.1)-(9.5)).
#include "collision/cuboid_separating_axis.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace tumble {
namespace {

/// (9.2) along the unit axis, with the normal turned to point from A towards B.
ContactAxis separationAlong(const CuboidFrame& a, const CuboidFrame& b, const Vec3& axis,
                            AxisKind kind, int axisA, int axisB)
{
    const Real centreDistance = glm::dot(b.centre - a.centre, axis);
    ContactAxis result;
    result.kind = kind;
    result.axisA = axisA;
    result.axisB = axisB;
    result.normal = centreDistance >= 0.0 ? axis : -axis;
    result.separation =
        std::abs(centreDistance) - projectedRadius(a, axis) - projectedRadius(b, axis);
    return result;
}

/// (9.5): does `candidate` beat `held` by the bias?
bool clearlyBetter(const ContactAxis& candidate, const ContactAxis& held)
{
    return candidate.separation >
           held.separation + kAxisRelativeBias * std::abs(held.separation) + kAxisAbsoluteBias;
}

} // namespace

Real projectedRadius(const CuboidFrame& box, const Vec3& axis)
{
    // (9.1): r = sum_k e_k |a_k . L|.
    return box.halfExtents.x * std::abs(glm::dot(box.axes[0], axis)) +
           box.halfExtents.y * std::abs(glm::dot(box.axes[1], axis)) +
           box.halfExtents.z * std::abs(glm::dot(box.axes[2], axis));
}

AxisSearch searchContactAxis(const CuboidFrame& a, const CuboidFrame& b, Real margin)
{
    // faces[k] for A's axis k, faces[3 + k] for B's.
    std::array<ContactAxis, 6> faces{};
    for (int k = 0; k < 3; ++k) {
        faces[k] = separationAlong(a, b, a.axes[k], AxisKind::FaceA, k, 0);
        faces[3 + k] = separationAlong(a, b, b.axes[k], AxisKind::FaceB, 0, k);
    }
    // Within each group the first axis of greatest separation is kept (strict >), so ties
    // resolve the same way every step.
    int faceA = 0;
    int faceB = 3;
    for (int k = 0; k < 3; ++k) {
        if (faces[k].separation > margin || faces[3 + k].separation > margin) {
            return {std::nullopt, std::max(faces[k].separation, faces[3 + k].separation)};
        }
        faceA = faces[k].separation > faces[faceA].separation ? k : faceA;
        faceB = faces[3 + k].separation > faces[faceB].separation ? 3 + k : faceB;
    }
    Real largest = std::max(faces[faceA].separation, faces[faceB].separation);
    std::optional<ContactAxis> edge;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            // (9.3): L = a_i x b_j / |a_i x b_j|, skipped when the edges are nearly parallel.
            const Vec3 cross = glm::cross(a.axes[i], b.axes[j]);
            const Real sine = glm::length(cross);
            if (sine < kParallelEdgeSine) {
                continue;
            }
            const ContactAxis axis =
                separationAlong(a, b, cross / sine, AxisKind::EdgePair, i, j);
            if (axis.separation > margin) {
                return {std::nullopt, axis.separation};
            }
            largest = std::max(largest, axis.separation);
            if (!edge || axis.separation > edge->separation) {
                edge = axis;
            }
        }
    }
    // (9.5): A's faces, then B's faces, then edge pairs, each replacing the held axis only when
    // clearly better.
    const ContactAxis& face =
        clearlyBetter(faces[faceB], faces[faceA]) ? faces[faceB] : faces[faceA];
    if (!edge || !clearlyBetter(*edge, face)) {
        return {face, largest};
    }
    // An edge axis nearly along a face normal gives way to that face, A's first.
    for (const ContactAxis& candidate : faces) {
        if (std::abs(glm::dot(candidate.normal, edge->normal)) >= kEdgeAxisFaceCosine) {
            return {candidate, largest};
        }
    }
    return {edge, largest};
}

std::optional<ContactAxis> findContactAxis(const CuboidFrame& a, const CuboidFrame& b,
                                           Real margin)
{
    return searchContactAxis(a, b, margin).axis;
}

} // namespace tumble
