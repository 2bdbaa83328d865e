// Separating-axis test between two cuboids (docs/physics/09-box-box.md, (9.1)-(9.5)), in the
// rotation-matrix form of (9.2a)-(9.2c) (Gottschalk et al. 1996; Ericson 2005, §4.4.1).
#include "collision/cuboid_separating_axis.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace tumble {
namespace {

/// B seen from A (9.2a): rotation[i][j] = a_i . b_j, its absolute values, and d = c_B - c_A in
/// A's frame (inA[i] = d . a_i) and in B's (inB[j] = d . b_j).
struct RelativePose {
    Vec3 offset{0.0};
    std::array<std::array<Real, 3>, 3> rotation{};
    std::array<std::array<Real, 3>, 3> absRotation{};
    std::array<Real, 3> inA{};
    std::array<Real, 3> inB{};
};

RelativePose relativePose(const CuboidFrame& a, const CuboidFrame& b)
{
    RelativePose pose;
    pose.offset = b.centre - a.centre;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            pose.rotation[i][j] = glm::dot(a.axes[i], b.axes[j]);
            pose.absRotation[i][j] = std::abs(pose.rotation[i][j]);
        }
        pose.inA[i] = glm::dot(pose.offset, a.axes[i]);
        pose.inB[i] = glm::dot(pose.offset, b.axes[i]);
    }
    return pose;
}

/// (9.2) on the six face axes (9.2b): [k] along a_k, [3 + k] along b_k.
std::array<Real, 6> faceSeparations(const CuboidFrame& a, const CuboidFrame& b,
                                    const RelativePose& pose)
{
    const Vec3& eA = a.halfExtents;
    const Vec3& eB = b.halfExtents;
    const auto& r = pose.absRotation;
    std::array<Real, 6> separation{};
    for (int k = 0; k < 3; ++k) {
        separation[k] = std::abs(pose.inA[k]) - eA[k] -
                        (eB.x * r[k][0] + eB.y * r[k][1] + eB.z * r[k][2]);
        separation[3 + k] = std::abs(pose.inB[k]) -
                            (eA.x * r[0][k] + eA.y * r[1][k] + eA.z * r[2][k]) - eB[k];
    }
    return separation;
}

/// An edge pair's axis (9.3) as far as the search needs it: no normal until it is chosen.
struct EdgeCandidate {
    int i = -1;  // axis of A; -1: none held
    int j = 0;   // axis of B
    Real sine = 0.0;        // |a_i x b_j|
    Real separation = 0.0;  // m, (9.2)
};

/// (9.2c) on L_ij, false for nearly parallel edges (9.3). In right-handed frames a_i x b_j has
/// the components (0, -R[i2][j], R[i1][j]) on (a_i, a_i1, a_i2) and (0, R[i][j2], -R[i][j1]) on
/// (b_j, b_j1, b_j2), i1 = i + 1 and so on mod 3. Only |d . (a_i x b_j)| and the absolute
/// components enter, so the separation holds for either handedness; the normal's sign is taken
/// from d itself (contactAxis).
bool edgeSeparation(const CuboidFrame& a, const CuboidFrame& b, const RelativePose& pose, int i,
                    int j, EdgeCandidate& edge)
{
    const int i1 = (i + 1) % 3;
    const int i2 = (i + 2) % 3;
    const int j1 = (j + 1) % 3;
    const int j2 = (j + 2) % 3;
    const auto& rotation = pose.rotation;
    const auto& r = pose.absRotation;
    const Real sine =
        std::sqrt(rotation[i1][j] * rotation[i1][j] + rotation[i2][j] * rotation[i2][j]);
    if (sine < kParallelEdgeSine) {
        return false;
    }
    const Real distance = pose.inA[i2] * rotation[i1][j] - pose.inA[i1] * rotation[i2][j];
    const Real radiusA = a.halfExtents[i1] * r[i2][j] + a.halfExtents[i2] * r[i1][j];
    const Real radiusB = b.halfExtents[j1] * r[i][j2] + b.halfExtents[j2] * r[i][j1];
    edge = EdgeCandidate{i, j, sine, (std::abs(distance) - radiusA - radiusB) / sine};
    return true;
}

/// The contact axis along `axis` (unit) with the normal turned from A towards B (9.2).
ContactAxis contactAxis(const Vec3& offset, const Vec3& axis, AxisKind kind, int axisA, int axisB,
                        Real separation)
{
    const Vec3 normal = glm::dot(offset, axis) >= 0.0 ? axis : -axis;
    return ContactAxis{kind, axisA, axisB, normal, separation};
}

/// Face axis `k` of faceSeparations' numbering.
ContactAxis faceContactAxis(const CuboidFrame& a, const CuboidFrame& b, const RelativePose& pose,
                            const std::array<Real, 6>& separation, int k)
{
    if (k < 3) {
        return contactAxis(pose.offset, a.axes[k], AxisKind::FaceA, k, 0, separation[k]);
    }
    return contactAxis(pose.offset, b.axes[k - 3], AxisKind::FaceB, 0, k - 3, separation[k]);
}

/// (9.5): does a candidate of separation `candidate` beat the held one of `held` by the bias?
bool clearlyBetter(Real candidate, Real held)
{
    return candidate > held + kAxisRelativeBias * std::abs(held) + kAxisAbsoluteBias;
}

/// (9.5) once an edge pair has beaten the faces: the edge axis, or the first face (A's, then
/// B's) whose normal lies within kEdgeAxisFaceCosine of it.
ContactAxis edgeOrNearbyFace(const CuboidFrame& a, const CuboidFrame& b, const RelativePose& pose,
                             const std::array<Real, 6>& separation, const EdgeCandidate& edge)
{
    const Vec3 axis = glm::cross(a.axes[edge.i], b.axes[edge.j]) / edge.sine;
    const ContactAxis edgeAxis =
        contactAxis(pose.offset, axis, AxisKind::EdgePair, edge.i, edge.j, edge.separation);
    for (int k = 0; k < 6; ++k) {
        const Vec3& faceAxis = k < 3 ? a.axes[k] : b.axes[k - 3];
        if (std::abs(glm::dot(faceAxis, edgeAxis.normal)) >= kEdgeAxisFaceCosine) {
            return faceContactAxis(a, b, pose, separation, k);
        }
    }
    return edgeAxis;
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
    const RelativePose pose = relativePose(a, b);
    const std::array<Real, 6> separation = faceSeparations(a, b, pose);
    // Within each group the first axis of greatest separation is kept (strict >), so ties
    // resolve the same way every step.
    int faceA = 0;
    int faceB = 3;
    for (int k = 0; k < 3; ++k) {
        if (separation[k] > margin || separation[3 + k] > margin) {
            return {std::nullopt, std::max(separation[k], separation[3 + k])};
        }
        faceA = separation[k] > separation[faceA] ? k : faceA;
        faceB = separation[3 + k] > separation[faceB] ? 3 + k : faceB;
    }
    Real largest = std::max(separation[faceA], separation[faceB]);
    EdgeCandidate edge;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            EdgeCandidate candidate;
            if (!edgeSeparation(a, b, pose, i, j, candidate)) {
                continue;
            }
            if (candidate.separation > margin) {
                return {std::nullopt, candidate.separation};
            }
            largest = std::max(largest, candidate.separation);
            if (edge.i < 0 || candidate.separation > edge.separation) {
                edge = candidate;
            }
        }
    }
    // (9.5): A's faces, then B's faces, then edge pairs, each replacing the held axis only when
    // clearly better.
    const int face = clearlyBetter(separation[faceB], separation[faceA]) ? faceB : faceA;
    if (edge.i < 0 || !clearlyBetter(edge.separation, separation[face])) {
        return {faceContactAxis(a, b, pose, separation, face), largest};
    }
    return {edgeOrNearbyFace(a, b, pose, separation, edge), largest};
}

std::optional<ContactAxis> findContactAxis(const CuboidFrame& a, const CuboidFrame& b,
                                           Real margin)
{
    return searchContactAxis(a, b, margin).axis;
}

} // namespace tumble
