// Cuboid-cuboid contact: a pure function of the two poses (docs/physics/09-box-box.md).
#include "collision/collide_cuboid_cuboid.hpp"

#include "collision/cuboid_face_clipping.hpp"
#include "collision/cuboid_features.hpp"
#include "collision/cuboid_separating_axis.hpp"

#include <algorithm>

namespace tumble {
namespace {

/// (9.10): one point midway between the closest points of the two support edges.
PairManifold edgeContact(const CuboidFrame& a, const CuboidFrame& b, const ContactAxis& axis)
{
    PairManifold manifold;
    manifold.normal = axis.normal;
    // A's edge farthest along the normal, B's farthest against it.
    const CuboidEdge edgeA = supportEdge(a, axis.axisA, axis.normal);
    const CuboidEdge edgeB = supportEdge(b, axis.axisB, -axis.normal);
    // Closest points of the lines x_A + s d_A and x_B + t d_B (unit directions), each parameter
    // then kept on its edge.
    const Vec3 offset = edgeA.midpoint - edgeB.midpoint;
    const Real cosine = glm::dot(edgeA.direction, edgeB.direction);
    const Real alongA = glm::dot(edgeA.direction, offset);
    const Real alongB = glm::dot(edgeB.direction, offset);
    // 1 - cosine^2 = |d_A x d_B|^2 >= kParallelEdgeSine^2 for a tested edge axis (9.3).
    const Real denominator = 1.0 - cosine * cosine;
    const Real s = std::clamp((cosine * alongB - alongA) / denominator, -edgeA.halfLength,
                              edgeA.halfLength);
    const Real t = std::clamp(alongB + s * cosine, -edgeB.halfLength, edgeB.halfLength);
    const Vec3 pointA = edgeA.midpoint + s * edgeA.direction;
    const Vec3 pointB = edgeB.midpoint + t * edgeB.direction;
    PairContactPoint& point = manifold.points[manifold.pointCount++];
    point.position = 0.5 * (pointA + pointB);
    point.separation = axis.separation;
    point.id = edgeContactId(edgeA.index, edgeB.index);
    return manifold;
}

/// (9.6)-(9.8): the reference face is on A for a FaceA axis, on B for a FaceB axis.
PairManifold faceContact(const CuboidFrame& a, const CuboidFrame& b, const ContactAxis& axis,
                         Real margin)
{
    const bool referenceIsB = axis.kind == AxisKind::FaceB;
    const CuboidFrame& reference = referenceIsB ? b : a;
    const CuboidFrame& incident = referenceIsB ? a : b;
    // The reference face faces the other box: along the normal on A, against it on B.
    const Vec3 outward = referenceIsB ? -axis.normal : axis.normal;
    const int referenceAxis = referenceIsB ? axis.axisB : axis.axisA;
    const bool negative = glm::dot(reference.axes[referenceAxis], outward) < 0.0;
    const int referenceFace = faceIndex(referenceAxis, negative);
    const ClippedPoints clipped =
        clipIncidentFace(reference, referenceFace, incident, referenceIsB, margin);
    return reduceContactPoints(clipped, axis.normal);
}

} // namespace

PairManifold collideCuboids(const Transform& poseA, const Vec3& halfExtentsA,
                            const Transform& poseB, const Vec3& halfExtentsB, Real margin)
{
    const CuboidFrame a = cuboidFrame(poseA, halfExtentsA);
    const CuboidFrame b = cuboidFrame(poseB, halfExtentsB);
    const std::optional<ContactAxis> axis = findContactAxis(a, b, margin);
    if (!axis) {
        return PairManifold{};
    }
    if (axis->kind == AxisKind::EdgePair) {
        return edgeContact(a, b, *axis);
    }
    return faceContact(a, b, *axis, margin);
}

} // namespace tumble
