// Scalar and vector types of tumble (glm, double precision) and the few helpers the physics needs.
#pragma once

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>

namespace tumble {

/// The one place precision is chosen: double, so results can be checked against closed-form
/// mechanics to tight tolerances.
using Real = double;
using Vec3 = glm::dvec3;
/// Unit quaternion. glm's constructor takes w first: Quat{w, x, y, z}; `quat * vec3` rotates.
using Quat = glm::dquat;
/// Column-major: m[column][row].
using Mat3 = glm::dmat3;

/// Position of the centre of mass and orientation of a body.
struct Transform {
    Vec3 position{0.0};
    Quat orientation{1.0, 0.0, 0.0, 0.0};
};

/// The matrix [v]x with [v]x u = cross(v, u).
inline Mat3 skew(const Vec3& v)
{
    // glm is column-major: each Vec3 below is a column.
    return Mat3(Vec3(0.0, v.z, -v.y), Vec3(-v.z, 0.0, v.x), Vec3(v.y, -v.x, 0.0));
}

inline Real lengthSquared(const Vec3& v) { return glm::dot(v, v); }

/// R D R^T for a diagonal body-frame tensor D = diag(diagonal): a body-frame inertia (or inverse
/// inertia) expressed in world axes (docs/physics/01-inertia.md, (1.3)).
inline Mat3 rotateDiagonalTensor(const Mat3& rotation, const Vec3& diagonal)
{
    Mat3 scaled = rotation;
    scaled[0] *= diagonal.x;
    scaled[1] *= diagonal.y;
    scaled[2] *= diagonal.z;
    return scaled * glm::transpose(rotation);
}

/// Rotation by `angle` radians about the unit vector `axis`.
inline Quat axisAngle(const Vec3& axis, Real angle)
{
    const Real half = 0.5 * angle;
    const Vec3 imaginary = std::sin(half) * axis;
    return Quat(std::cos(half), imaginary.x, imaginary.y, imaginary.z);
}

/// Two unit tangents completing the unit normal n to a right-handed orthonormal basis
/// (Duff et al. 2017, "Building an orthonormal basis, revisited": no branch on a threshold).
inline void orthonormalBasis(const Vec3& n, Vec3& tangent1, Vec3& tangent2)
{
    const Real sign = std::copysign(1.0, n.z);
    const Real a = -1.0 / (sign + n.z);
    const Real b = n.x * n.y * a;
    tangent1 = Vec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    tangent2 = Vec3(b, sign + n.y * n.y * a, -n.y);
}

inline bool isFinite(const Vec3& v)
{
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

inline bool isFinite(const Quat& q)
{
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

} // namespace tumble
