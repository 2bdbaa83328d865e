// Mass properties and geometry of the cuboid (docs/physics/01-inertia.md).
#include "tumble/shape.hpp"

#include <cmath>

namespace tumble {

Vec3 cuboidInertiaDiagonal(Real mass, const Vec3& size)
{
    // (1.1): I0 = m/12 diag(h^2 + d^2, w^2 + d^2, w^2 + h^2) with (w, h, d) = size.
    const Vec3 squared = size * size;
    return (mass / 12.0) *
           Vec3(squared.y + squared.z, squared.x + squared.z, squared.x + squared.y);
}

Vec3 cuboidInverseInertiaDiagonal(Real mass, const Vec3& size)
{
    // (1.2): the inverse of a diagonal tensor is the diagonal of reciprocals.
    return 1.0 / cuboidInertiaDiagonal(mass, size);
}

std::array<Vec3, 8> cuboidVertices(const Vec3& halfExtents)
{
    std::array<Vec3, 8> vertices{};
    for (int i = 0; i < 8; ++i) {
        vertices[i] = Vec3((i & 1) ? halfExtents.x : -halfExtents.x,
                           (i & 2) ? halfExtents.y : -halfExtents.y,
                           (i & 4) ? halfExtents.z : -halfExtents.z);
    }
    return vertices;
}

const char* faceName(CuboidFace face)
{
    switch (face) {
    case CuboidFace::PlusX: return "+x";
    case CuboidFace::MinusX: return "-x";
    case CuboidFace::PlusY: return "+y";
    case CuboidFace::MinusY: return "-y";
    case CuboidFace::PlusZ: return "+z";
    case CuboidFace::MinusZ: return "-z";
    }
    return "?";
}

CuboidFace faceAlong(const Quat& orientation, const Vec3& worldDirection)
{
    // The body-frame direction; its largest component (by magnitude) names the face.
    const Vec3 local = glm::conjugate(orientation) * worldDirection;
    const Vec3 magnitude = glm::abs(local);
    if (magnitude.x >= magnitude.y && magnitude.x >= magnitude.z) {
        return local.x >= 0.0 ? CuboidFace::PlusX : CuboidFace::MinusX;
    }
    if (magnitude.y >= magnitude.z) {
        return local.y >= 0.0 ? CuboidFace::PlusY : CuboidFace::MinusY;
    }
    return local.z >= 0.0 ? CuboidFace::PlusZ : CuboidFace::MinusZ;
}

} // namespace tumble
