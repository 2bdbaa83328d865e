// Shapes (the cuboid a body is, the ground plane, static half-spaces) and the cuboid's mass properties.
#pragma once

#include "tumble/material.hpp"
#include "tumble/math.hpp"

#include <array>
#include <optional>

namespace tumble {

/// A solid cuboid of uniform density, centred on the body's centre of mass.
struct Cuboid {
    /// Full extents along the body's x (width), y (height) and z (depth) axes, m.
    /// Default: the 2 x 2 x 2 cube of the handouts.
    Vec3 size{2.0, 2.0, 2.0};

    [[nodiscard]] Vec3 halfExtents() const { return 0.5 * size; }
};

/// The horizontal ground: the plane y = height with upward normal +y.
struct Plane {
    /// Height of the plane, m. Default 0.
    Real height = 0.0;

    [[nodiscard]] static Vec3 normal() { return Vec3(0.0, 1.0, 0.0); }
};

/// A static half-space of any orientation: the points x with n . (x - point) <= 0 are inside.
struct StaticPlane {
    /// A point on the boundary plane, m.
    Vec3 point{0.0};
    /// Outward unit normal. Default +y.
    Vec3 normal{0.0, 1.0, 0.0};
    /// The plane's own material, or none: its contacts then take the dynamic body's.
    std::optional<Material> material;
};

/// Diagonal of the body-frame inertia tensor of a solid cuboid, kg m^2
/// (docs/physics/01-inertia.md, (1.1)): I0 = m/12 diag(h^2 + d^2, w^2 + d^2, w^2 + h^2).
Vec3 cuboidInertiaDiagonal(Real mass, const Vec3& size);

/// Diagonal of the inverse of that tensor, 1/(kg m^2) (docs/physics/01-inertia.md, (1.2)).
Vec3 cuboidInverseInertiaDiagonal(Real mass, const Vec3& size);

/// The 8 corners of a cuboid in body coordinates. Vertex i has the sign pattern
/// (bit 0 -> x, bit 1 -> y, bit 2 -> z; bit set = +half extent).
std::array<Vec3, 8> cuboidVertices(const Vec3& halfExtents);

/// Faces named by their outward body-frame normal, in the order +x, -x, +y, -y, +z, -z.
enum class CuboidFace { PlusX, MinusX, PlusY, MinusY, PlusZ, MinusZ };

/// "+x", "-x", "+y", "-y", "+z" or "-z".
const char* faceName(CuboidFace face);

/// The face whose outward normal points most nearly along `worldDirection` for a body with the
/// given orientation (the face down is faceAlong(orientation, -up)).
CuboidFace faceAlong(const Quat& orientation, const Vec3& worldDirection);

/// How deep two cuboids at their poses overlap, m: the penetration along the separating axis of
/// least penetration (docs/physics/09-box-box.md, (9.4)); zero or negative when they are apart.
Real cuboidOverlapDepth(const Transform& poseA, const Vec3& halfExtentsA, const Transform& poseB,
                        const Vec3& halfExtentsB);

/// How deep the cuboid's lowest vertex lies inside the half-space, m (negative: above its plane).
Real cuboidHalfSpaceDepth(const Transform& pose, const Vec3& halfExtents, const StaticPlane& plane);

} // namespace tumble
