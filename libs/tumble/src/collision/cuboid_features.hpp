// Faces and edges of a posed cuboid, named as shape.hpp names them, for box-box contact
// (docs/physics/09-box-box.md).
#pragma once

#include "tumble/math.hpp"

#include <array>
#include <cstdint>

namespace tumble {

/// A cuboid in world coordinates: centre, unit axes (the columns of R) and half extents.
struct CuboidFrame {
    Vec3 centre{0.0};
    std::array<Vec3, 3> axes{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    Vec3 halfExtents{1.0};
};

CuboidFrame cuboidFrame(const Transform& pose, const Vec3& halfExtents);

/// Face index in CuboidFace order (+x, -x, +y, -y, +z, -z): 2 axis + (1 if the outward normal
/// is -axes[axis]).
inline int faceIndex(int axis, bool negative) { return 2 * axis + (negative ? 1 : 0); }
inline int faceAxis(int face) { return face / 2; }
inline Real faceSign(int face) { return (face % 2 == 0) ? 1.0 : -1.0; }

/// Outward unit normal of a face, world frame.
Vec3 faceNormal(const CuboidFrame& box, int face);

/// The 4 corners of a face in a fixed cyclic order: corner m and m+1 (mod 4) bound face edge m.
/// With (j1, j2) = (axis+1, axis+2) mod 3 the corners have the tangent signs (-,-), (+,-), (+,+),
/// (-,+); the order depends on the face index only, so feature ids built on it are stable.
std::array<Vec3, 4> faceCorners(const CuboidFrame& box, int face);

/// One edge of a cuboid: along axes[axis], through the point centre + sum of +-half extents on
/// the other two axes. Index 4 axis + (bit 0: + on axis+1, bit 1: + on axis+2), so 0..11.
struct CuboidEdge {
    Vec3 midpoint{0.0};
    Vec3 direction{1.0, 0.0, 0.0};  // unit, = axes[axis]
    Real halfLength = 0.0;
    int index = 0;
};

/// The edge along axes[axis] farthest along `direction` (ties go to the + side).
CuboidEdge supportEdge(const CuboidFrame& box, int axis, const Vec3& direction);

/// Feature id of a point clipped from an incident face (docs/physics/09-box-box.md, (9.9)):
/// bits 0-3 the incident face edges (edge m runs from corner m to m+1) the point lies on, bits
/// 4-7 the side planes of the reference face it lies on, bits 8-10 the incident face, bits 11-13
/// the reference face, bit 14 set when the reference face is B's. Bit 15 is clear.
inline std::uint32_t faceContactId(bool referenceIsB, int referenceFace, int incidentFace,
                                   unsigned incidentEdges, unsigned sidePlanes)
{
    return (incidentEdges & 0xFu) | ((sidePlanes & 0xFu) << 4) |
           (static_cast<std::uint32_t>(incidentFace) << 8) |
           (static_cast<std::uint32_t>(referenceFace) << 11) | (referenceIsB ? 1u << 14 : 0u);
}

/// Feature id of an edge-edge point (9.9): bit 15 set, bits 0-3 A's edge, bits 4-7 B's edge
/// (CuboidEdge::index).
inline std::uint32_t edgeContactId(int edgeA, int edgeB)
{
    return (1u << 15) | static_cast<std::uint32_t>(edgeA) |
           (static_cast<std::uint32_t>(edgeB) << 4);
}

} // namespace tumble
