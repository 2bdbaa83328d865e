// Face contact between two cuboids: clipping and reduction (docs/physics/09-box-box.md,
// (9.6)-(9.9)).
#include "collision/cuboid_face_clipping.hpp"

#include <cmath>

namespace tumble {
namespace {

/// A vertex of the polygon being clipped, in the reference face's frame (9.7): `at` holds its
/// coordinates along the side axes a_j1, a_j2 and the face normal, from the reference centre.
/// `features` holds what it lies on: bits 0-3 the incident face's edges (bit m: edge m), bits
/// 4-7 the reference face's side planes (bit 4 + p: plane p), as faceContactId packs them.
struct ClipVertex {
    std::array<Real, 3> at;
    unsigned features;
};

struct Polygon {
    std::array<ClipVertex, kMaxClippedPoints> vertices;
    int count = 0;
};

/// A vertex within this share of the half-width of a side plane lies on it (9.7): incident
/// corners on the reference face's edges up to rounding stay, and an edge along a side is not
/// cut.
constexpr Real kOnSidePlane = 1e-9;

/// One Sutherland-Hodgman pass (9.7) by side plane p of half-width `extent`: writes into
/// `output` the part of the convex polygon `input` inside it. Plane p bounds side coordinate
/// p % 2, from above for p < 2 and from below for p >= 2: +x_1 <= e_j1, +x_2 <= e_j2,
/// -x_1 <= e_j1, -x_2 <= e_j2. A vertex within kOnSidePlane of the plane lies on it: it stays,
/// and no crossing is made next to it. A vertex made on an edge (a, b) lies on the features a
/// and b share, and on plane p. Returns false, writing nothing, when no vertex lies outside:
/// the pass would copy `input` as it is.
bool clipBySide(const Polygon& input, int p, Real extent, Polygon& output)
{
    const int coordinate = p % 2;
    const Real sign = p < 2 ? 1.0 : -1.0;
    const Real onPlane = kOnSidePlane * extent;
    std::array<Real, kMaxClippedPoints> distances;
    bool outside = false;
    for (int i = 0; i < input.count; ++i) {
        const Real distance = sign * input.vertices[i].at[coordinate] - extent;
        distances[i] = std::abs(distance) <= onPlane ? 0.0 : distance;
        outside = outside || distances[i] > 0.0;
    }
    if (!outside) {
        return false;
    }
    output.count = 0;
    for (int i = 0; i < input.count; ++i) {
        const int next = i + 1 == input.count ? 0 : i + 1;
        const ClipVertex& a = input.vertices[i];
        const ClipVertex& b = input.vertices[next];
        const Real distanceA = distances[i];
        const Real distanceB = distances[next];
        if (distanceA <= 0.0) {
            output.vertices[output.count++] = a;
        }
        if ((distanceA < 0.0 && distanceB > 0.0) || (distanceA > 0.0 && distanceB < 0.0)) {
            // The signs differ, so distanceA - distanceB is not zero.
            const Real t = distanceA / (distanceA - distanceB);
            ClipVertex& crossing = output.vertices[output.count++];
            for (int k = 0; k < 3; ++k) {
                crossing.at[k] = a.at[k] + t * (b.at[k] - a.at[k]);
            }
            crossing.features = (a.features & b.features) | (1u << (4 + p));
        }
    }
    return true;
}

/// The incident face's corners in the reference face's frame (9.7a) (rows: a_j1, a_j2, normal),
/// in faceCorners' order, each on the two incident edges it bounds: corner m closes edge m - 1
/// and opens edge m.
void incidentCorners(const CuboidFrame& reference, const std::array<Vec3, 3>& frame,
                     const CuboidFrame& incident, int incidentFace, Polygon& polygon)
{
    const int axis = faceAxis(incidentFace);
    const int i1 = (axis + 1) % 3;
    const int i2 = (axis + 2) % 3;
    const Vec3 offset = incident.centre +
                        faceSign(incidentFace) * incident.halfExtents[axis] * incident.axes[axis] -
                        reference.centre;
    const Vec3 u = incident.halfExtents[i1] * incident.axes[i1];
    const Vec3 v = incident.halfExtents[i2] * incident.axes[i2];
    constexpr std::array<Real, 4> kSignU{-1.0, 1.0, 1.0, -1.0};
    constexpr std::array<Real, 4> kSignV{-1.0, -1.0, 1.0, 1.0};
    polygon.count = 4;
    for (int k = 0; k < 3; ++k) {
        const Real centreAt = glm::dot(frame[k], offset);
        const Real uAt = glm::dot(frame[k], u);
        const Real vAt = glm::dot(frame[k], v);
        for (int m = 0; m < 4; ++m) {
            polygon.vertices[m].at[k] = centreAt + kSignU[m] * uAt + kSignV[m] * vAt;
        }
    }
    for (int m = 0; m < 4; ++m) {
        polygon.vertices[m].features = (1u << m) | (1u << ((m + 3) % 4));
    }
}

/// Twice the signed area of the triangle (a, b, c) seen along `normal`.
Real signedArea(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& normal)
{
    return glm::dot(glm::cross(b - a, c - a), normal);
}

/// The point that adds the most area to the counter-clockwise triangle: the largest area
/// beyond one of its edges (9.8); -1 if every point lies inside it.
int largestAreaGain(const ClippedPoints& clipped, const std::array<int, 3>& triangle,
                    const Vec3& normal)
{
    int best = -1;
    Real bestGain = 0.0;
    for (int i = 0; i < clipped.count; ++i) {
        for (int e = 0; e < 3; ++e) {
            const Real gain = -signedArea(clipped.points[triangle[e]].position,
                                          clipped.points[triangle[(e + 1) % 3]].position,
                                          clipped.points[i].position, normal);
            if (gain > bestGain) {
                best = i;
                bestGain = gain;
            }
        }
    }
    return best;
}

} // namespace

int incidentFaceIndex(const CuboidFrame& box, const Vec3& referenceNormal)
{
    // (9.6): the axis most nearly parallel to the reference normal; the face on it whose outward
    // normal points against the reference normal. Ties go to the lower axis.
    int best = 0;
    Real bestDot = glm::dot(box.axes[0], referenceNormal);
    for (int k = 1; k < 3; ++k) {
        const Real along = glm::dot(box.axes[k], referenceNormal);
        if (std::abs(along) > std::abs(bestDot)) {
            best = k;
            bestDot = along;
        }
    }
    return faceIndex(best, bestDot > 0.0);
}

ClippedPoints clipIncidentFace(const CuboidFrame& reference, int referenceFace,
                               const CuboidFrame& incident, bool referenceIsB, Real margin)
{
    const Vec3 normal = faceNormal(reference, referenceFace);
    const int incidentFace = incidentFaceIndex(incident, normal);
    const int axis = faceAxis(referenceFace);
    const int j1 = (axis + 1) % 3;
    const int j2 = (axis + 2) % 3;
    const std::array<Vec3, 3> frame{reference.axes[j1], reference.axes[j2], normal};
    // Clipped back and forth between two polygons: a pass that cuts reads one and writes the
    // other.
    std::array<Polygon, 2> polygons;
    incidentCorners(reference, frame, incident, incidentFace, polygons[0]);
    int current = 0;
    for (int p = 0; p < 4 && polygons[current].count > 0; ++p) {
        if (clipBySide(polygons[current], p, reference.halfExtents[p % 2 == 0 ? j1 : j2],
                       polygons[1 - current])) {
            current = 1 - current;
        }
    }
    // (9.7): separation below the reference face; the point reported midway between surfaces,
    // x - (s/2) n = c_R + x_1 a_j1 + x_2 a_j2 + (e_k + s/2) n.
    const Real faceOffset = reference.halfExtents[axis];
    const Polygon& polygon = polygons[current];
    ClippedPoints clipped;
    for (int i = 0; i < polygon.count; ++i) {
        const ClipVertex& vertex = polygon.vertices[i];
        const Real separation = vertex.at[2] - faceOffset;
        if (separation > margin) {
            continue;
        }
        PairContactPoint& point = clipped.points[clipped.count++];
        point.position = reference.centre + vertex.at[0] * frame[0] + vertex.at[1] * frame[1] +
                         (faceOffset + 0.5 * separation) * normal;
        point.separation = separation;
        point.id = faceContactId(referenceIsB, referenceFace, incidentFace,
                                 vertex.features & 0xFu, vertex.features >> 4);
    }
    return clipped;
}

void reduceContactPoints(const ClippedPoints& clipped, const Vec3& normal,
                         PairManifold& manifold)
{
    manifold.normal = normal;
    manifold.pointCount = 0;
    if (clipped.count <= 4) {
        for (int i = 0; i < clipped.count; ++i) {
            manifold.points[manifold.pointCount++] = clipped.points[i];
        }
        return;
    }
    const auto& points = clipped.points;
    const auto at = [&](int i) { return points[i].position; };
    // (9.8) first: the deepest point, then the one farthest from it (first of equals).
    int first = 0;
    int second = 0;
    for (int i = 1; i < clipped.count; ++i) {
        first = points[i].separation < points[first].separation ? i : first;
    }
    for (int i = 0; i < clipped.count; ++i) {
        const bool farther =
            lengthSquared(at(i) - at(first)) > lengthSquared(at(second) - at(first));
        second = farther ? i : second;
    }
    // Third: the largest triangle on that segment, either side.
    int third = 0;
    for (int i = 1; i < clipped.count; ++i) {
        const bool larger = std::abs(signedArea(at(first), at(second), at(i), normal)) >
                            std::abs(signedArea(at(first), at(second), at(third), normal));
        third = larger ? i : third;
    }
    const Real thirdArea = signedArea(at(first), at(second), at(third), normal);
    if (thirdArea == 0.0) {
        // All points on one line (not reached by a convex clipped face): keep its two ends.
        manifold.points[0] = points[first];
        manifold.points[1] = points[second];
        manifold.pointCount = 2;
        return;
    }
    // Counter-clockwise about the normal, so the area beyond an edge is the negative one.
    const std::array<int, 3> triangle =
        thirdArea > 0.0 ? std::array<int, 3>{first, second, third}
                        : std::array<int, 3>{second, first, third};
    const int fourth = largestAreaGain(clipped, triangle, normal);
    for (const int index : triangle) {
        manifold.points[manifold.pointCount++] = points[index];
    }
    if (fourth >= 0) {
        manifold.points[manifold.pointCount++] = points[fourth];
    }
}

} // namespace tumble
