// Cuboid-cuboid contact: a pure function of the two poses (docs/physics/09-box-box.md).
#include "collision/collide_cuboid_cuboid.hpp"

#include "collision/cuboid_face_clipping.hpp"
#include "collision/cuboid_features.hpp"
#include "collision/cuboid_separating_axis.hpp"

#include <algorithm>
#include <limits>

namespace tumble {
namespace {

/// (9.10): one point midway between the closest points of the two support edges.
ClippedPoints edgeContact(const CuboidFrame& a, const CuboidFrame& b, const ContactAxis& axis)
{
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
    ClippedPoints contact;
    PairContactPoint& point = contact.points[contact.count++];
    point.position = 0.5 * (pointA + pointB);
    point.separation = axis.separation;
    point.id = edgeContactId(edgeA.index, edgeB.index);
    return contact;
}

/// (9.6)-(9.7) at every separation: the reference face is on A for a FaceA axis, on B for a
/// FaceB axis.
ClippedPoints faceContact(const CuboidFrame& a, const CuboidFrame& b, const ContactAxis& axis)
{
    const bool referenceIsB = axis.kind == AxisKind::FaceB;
    const CuboidFrame& reference = referenceIsB ? b : a;
    const CuboidFrame& incident = referenceIsB ? a : b;
    // The reference face faces the other box: along the normal on A, against it on B.
    const Vec3 outward = referenceIsB ? -axis.normal : axis.normal;
    const int referenceAxis = referenceIsB ? axis.axisB : axis.axisA;
    const bool negative = glm::dot(reference.axes[referenceAxis], outward) < 0.0;
    const int referenceFace = faceIndex(referenceAxis, negative);
    return clipIncidentFace(reference, referenceFace, incident, referenceIsB,
                            std::numeric_limits<Real>::infinity());
}

} // namespace

CuboidPairGeometry findCuboidPairGeometry(const CuboidFrame& a, const CuboidFrame& b,
                                          Real margin)
{
    const AxisSearch search = searchContactAxis(a, b, margin);
    CuboidPairGeometry geometry;
    geometry.largestSeparation = search.largestSeparation;
    geometry.complete = search.axis.has_value();
    if (!search.axis) {
        return geometry;
    }
    geometry.normal = search.axis->normal;
    geometry.normalOfB = search.axis->kind == AxisKind::FaceB;
    geometry.points = search.axis->kind == AxisKind::EdgePair ? edgeContact(a, b, *search.axis)
                                                               : faceContact(a, b, *search.axis);
    return geometry;
}

bool decidesMargin(const CuboidPairGeometry& geometry, Real margin)
{
    return geometry.complete || geometry.largestSeparation > margin;
}

void writeManifoldWithin(const CuboidPairGeometry& geometry, Real margin,
                         PairManifold& manifold)
{
    manifold.pointCount = 0;
    if (geometry.largestSeparation > margin) {
        return;
    }
    // the clipped points within the margin, in clipping order (9.7); the edge point's separation
    // is that of its axis, never above the largest
    const auto isWithin = [&](const PairContactPoint& point) { return point.separation <= margin; };
    const auto begin = geometry.points.points.begin();
    const auto end = begin + geometry.points.count;
    const auto within = std::count_if(begin, end, isWithin);
    if (within == geometry.points.count) {
        // all of them: reduced where they lie (9.8)
        reduceContactPoints(geometry.points, geometry.normal, manifold);
        return;
    }
    if (within <= 4) {
        // nothing to reduce (9.8)
        manifold.normal = geometry.normal;
        for (auto point = begin; point != end; ++point) {
            if (isWithin(*point)) {
                manifold.points[manifold.pointCount++] = *point;
            }
        }
        return;
    }
    ClippedPoints kept;
    kept.count = static_cast<int>(std::copy_if(begin, end, kept.points.begin(), isWithin) -
                                  kept.points.begin());
    reduceContactPoints(kept, geometry.normal, manifold);
}

PairManifold manifoldWithin(const CuboidPairGeometry& geometry, Real margin)
{
    PairManifold manifold;
    writeManifoldWithin(geometry, margin, manifold);
    return manifold;
}

PairManifold collideCuboids(const Transform& poseA, const Vec3& halfExtentsA,
                            const Transform& poseB, const Vec3& halfExtentsB, Real margin)
{
    return manifoldWithin(findCuboidPairGeometry(cuboidFrame(poseA, halfExtentsA),
                                                 cuboidFrame(poseB, halfExtentsB), margin),
                          margin);
}

} // namespace tumble
