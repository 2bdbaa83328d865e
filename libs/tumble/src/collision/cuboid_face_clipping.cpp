// Face contact between two cuboids: clipping and reduction (docs/physics/09-box-box.md,
// (9.6)-(9.9)).
#include "collision/cuboid_face_clipping.hpp"

#include <cmath>

namespace tumble {
namespace {

/// A vertex of the polygon being clipped, with the features it lies on: the incident face's
/// edges (bit m: edge m) and the reference face's side planes (bit p: plane p).
struct ClipVertex {
    Vec3 position{0.0};
    unsigned edges = 0;
    unsigned planes = 0;
};

struct Polygon {
    std::array<ClipVertex, kMaxClippedPoints> vertices{};
    int count = 0;
};

/// Side plane p of the reference face: the points x with dot(normal, x - centre) <= extent.
/// A vertex within this share of the half-width of a side plane lies on it (9.7): incident
/// corners on the reference face's edges up to rounding stay, and an edge along a side is not
/// cut.
constexpr Real kOnSidePlane = 1e-9;

struct SidePlane {
    Vec3 normal{0.0};
    Real extent = 0.0;
};

/// One Sutherland-Hodgman pass (9.7): keeps the part of the convex polygon inside the plane.
/// A vertex within kOnSidePlane of the plane lies on it: it stays, and no crossing is made next
/// to it. A vertex made on an edge (a, b) lies on the features a and b share, and on plane
/// `index`.
Polygon clipByPlane(const Polygon& input, const SidePlane& plane, const Vec3& centre, int index)
{
    const Real onPlane = kOnSidePlane * plane.extent;
    const auto distanceOf = [&](const ClipVertex& v) {
        const Real distance = glm::dot(plane.normal, v.position - centre) - plane.extent;
        return std::abs(distance) <= onPlane ? 0.0 : distance;
    };
    Polygon output;
    for (int i = 0; i < input.count; ++i) {
        const ClipVertex& a = input.vertices[i];
        const ClipVertex& b = input.vertices[(i + 1) % input.count];
        const Real distanceA = distanceOf(a);
        const Real distanceB = distanceOf(b);
        if (distanceA <= 0.0) {
            output.vertices[output.count++] = a;
        }
        if ((distanceA < 0.0 && distanceB > 0.0) || (distanceA > 0.0 && distanceB < 0.0)) {
            // The signs differ, so distanceA - distanceB is not zero.
            const Real t = distanceA / (distanceA - distanceB);
            ClipVertex& crossing = output.vertices[output.count++];
            crossing.position = a.position + t * (b.position - a.position);
            crossing.edges = a.edges & b.edges;
            crossing.planes = (a.planes & b.planes) | (1u << index);
        }
    }
    return output;
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
    const int incidentFace = incidentFaceIndex(incident, faceNormal(reference, referenceFace));
    const std::array<Vec3, 4> corners = faceCorners(incident, incidentFace);
    Polygon polygon;
    polygon.count = 4;
    for (int m = 0; m < 4; ++m) {
        // Corner m closes edge m - 1 and opens edge m.
        polygon.vertices[m] = ClipVertex{corners[m], (1u << m) | (1u << ((m + 3) % 4)), 0u};
    }
    const int axis = faceAxis(referenceFace);
    const int j1 = (axis + 1) % 3;
    const int j2 = (axis + 2) % 3;
    const std::array<SidePlane, 4> sides{
        SidePlane{reference.axes[j1], reference.halfExtents[j1]},
        SidePlane{reference.axes[j2], reference.halfExtents[j2]},
        SidePlane{-reference.axes[j1], reference.halfExtents[j1]},
        SidePlane{-reference.axes[j2], reference.halfExtents[j2]},
    };
    for (int p = 0; p < 4 && polygon.count > 0; ++p) {
        polygon = clipByPlane(polygon, sides[p], reference.centre, p);
    }
    // (9.7): separation below the reference face; the point reported midway between surfaces.
    const Vec3 normal = faceNormal(reference, referenceFace);
    const Real faceOffset = reference.halfExtents[axis];
    ClippedPoints clipped;
    for (int i = 0; i < polygon.count; ++i) {
        const ClipVertex& vertex = polygon.vertices[i];
        const Real separation = glm::dot(normal, vertex.position - reference.centre) - faceOffset;
        if (separation > margin) {
            continue;
        }
        PairContactPoint& point = clipped.points[clipped.count++];
        point.position = vertex.position - 0.5 * separation * normal;
        point.separation = separation;
        point.id = faceContactId(referenceIsB, referenceFace, incidentFace, vertex.edges,
                                 vertex.planes);
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
