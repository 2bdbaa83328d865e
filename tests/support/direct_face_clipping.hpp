// The incident face clipping of (9.7) in the direct form, as a reference for clipIncidentFace:
// the incident face's corners in world coordinates clipped by the reference face's 4 side planes
// in world space (Sutherland-Hodgman), a 3D dot product per vertex and plane. It also notes how
// close its decisions came to going the other way, and how well its crossings are conditioned.
#pragma once

#include "collision/cuboid_face_clipping.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace tumble::testing {

/// The on-plane share of (9.7), as the library has it.
inline constexpr Real kDirectOnSidePlane = 1e-9;

struct DirectClipVertex {
    Vec3 position{0.0};
    unsigned edges = 0;
    unsigned planes = 0;
};

struct DirectPolygon {
    std::array<DirectClipVertex, kMaxClippedPoints> vertices{};
    int count = 0;
};

struct DirectSidePlane {
    Vec3 normal{0.0};
    Real extent = 0.0;
};

/// What the reference found besides its points.
struct DirectClipping {
    ClippedPoints clipped;
    /// The smallest gap between a quantity and the threshold it was compared with (a side
    /// distance and kDirectOnSidePlane extent, a separation and the margin): a decision within
    /// rounding of its threshold may go either way in another form. (A distance outside the
    /// snap is far from 0, so its sign is clear-cut.)
    Real closestDecision = std::numeric_limits<Real>::infinity();
    /// The smallest |delta_a - delta_b| / |b - a| of a crossing made: the sine of the angle
    /// between the clipped edge and the plane. A crossing's position carries the rounding of
    /// its distances divided by it.
    Real crossingSine = 1.0;
};

/// One Sutherland-Hodgman pass in world space.
inline DirectPolygon directClipByPlane(const DirectPolygon& input, const DirectSidePlane& plane,
                                       const Vec3& centre, int index, DirectClipping& notes)
{
    const Real onPlane = kDirectOnSidePlane * plane.extent;
    const auto distanceOf = [&](const DirectClipVertex& v) {
        const Real distance = glm::dot(plane.normal, v.position - centre) - plane.extent;
        notes.closestDecision =
            std::min(notes.closestDecision, std::abs(std::abs(distance) - onPlane));
        return std::abs(distance) <= onPlane ? 0.0 : distance;
    };
    DirectPolygon output;
    for (int i = 0; i < input.count; ++i) {
        const DirectClipVertex& a = input.vertices[i];
        const DirectClipVertex& b = input.vertices[(i + 1) % input.count];
        const Real distanceA = distanceOf(a);
        const Real distanceB = distanceOf(b);
        if (distanceA <= 0.0) {
            output.vertices[output.count++] = a;
        }
        if ((distanceA < 0.0 && distanceB > 0.0) || (distanceA > 0.0 && distanceB < 0.0)) {
            const Real t = distanceA / (distanceA - distanceB);
            DirectClipVertex& crossing = output.vertices[output.count++];
            crossing.position = a.position + t * (b.position - a.position);
            crossing.edges = a.edges & b.edges;
            crossing.planes = (a.planes & b.planes) | (1u << index);
            notes.crossingSine =
                std::min(notes.crossingSine, std::abs(distanceA - distanceB) /
                                                 glm::length(b.position - a.position));
        }
    }
    return output;
}

/// (9.6)-(9.7) in world space: the points, positions, separations and ids clipIncidentFace
/// must give.
inline DirectClipping directClipIncidentFace(const CuboidFrame& reference, int referenceFace,
                                             const CuboidFrame& incident, bool referenceIsB,
                                             Real margin)
{
    DirectClipping notes;
    const int incidentFace = incidentFaceIndex(incident, faceNormal(reference, referenceFace));
    const std::array<Vec3, 4> corners = faceCorners(incident, incidentFace);
    DirectPolygon polygon;
    polygon.count = 4;
    for (int m = 0; m < 4; ++m) {
        polygon.vertices[m] =
            DirectClipVertex{corners[m], (1u << m) | (1u << ((m + 3) % 4)), 0u};
    }
    const int axis = faceAxis(referenceFace);
    const int j1 = (axis + 1) % 3;
    const int j2 = (axis + 2) % 3;
    const std::array<DirectSidePlane, 4> sides{
        DirectSidePlane{reference.axes[j1], reference.halfExtents[j1]},
        DirectSidePlane{reference.axes[j2], reference.halfExtents[j2]},
        DirectSidePlane{-reference.axes[j1], reference.halfExtents[j1]},
        DirectSidePlane{-reference.axes[j2], reference.halfExtents[j2]},
    };
    for (int p = 0; p < 4 && polygon.count > 0; ++p) {
        polygon = directClipByPlane(polygon, sides[p], reference.centre, p, notes);
    }
    const Vec3 normal = faceNormal(reference, referenceFace);
    const Real faceOffset = reference.halfExtents[axis];
    for (int i = 0; i < polygon.count; ++i) {
        const DirectClipVertex& vertex = polygon.vertices[i];
        const Real separation = glm::dot(normal, vertex.position - reference.centre) - faceOffset;
        notes.closestDecision = std::min(notes.closestDecision, std::abs(separation - margin));
        if (separation > margin) {
            continue;
        }
        PairContactPoint& point = notes.clipped.points[notes.clipped.count++];
        point.position = vertex.position - 0.5 * separation * normal;
        point.separation = separation;
        point.id = faceContactId(referenceIsB, referenceFace, incidentFace, vertex.edges,
                                 vertex.planes);
    }
    return notes;
}

} // namespace tumble::testing
