// Boxes of a cuboid at a pose and over a step (docs/physics/10-broad-phase.md, (10.1)-(10.3)).
#include "collision/aabb.hpp"

#include <cmath>

namespace tumble {
namespace {

/// Half widths of the rotated cuboid along the world axes (10.1).
Vec3 rotatedHalfWidths(const Quat& orientation, const Vec3& halfExtents)
{
    // glm is column-major: rotation[k] is the world image of body axis k, so component i of
    // |rotation[k]| is |R_ik|.
    const Mat3 rotation = glm::mat3_cast(orientation);
    return glm::abs(rotation[0]) * halfExtents.x + glm::abs(rotation[1]) * halfExtents.y +
           glm::abs(rotation[2]) * halfExtents.z;
}

/// Smallest and largest value of p(s) = x + v s + a s^2/2 over s in [0, dt] (10.2): the ends and,
/// where it falls inside, the vertex s = -v/a.
void ballisticRange(Real x, Real v, Real a, Real dt, Real& lowest, Real& highest)
{
    const Real end = x + v * dt + 0.5 * a * dt * dt;
    lowest = std::min(x, end);
    highest = std::max(x, end);
    if (a != 0.0) {
        const Real vertexTime = -v / a;
        if (vertexTime > 0.0 && vertexTime < dt) {
            const Real vertex = x + 0.5 * v * vertexTime;
            lowest = std::min(lowest, vertex);
            highest = std::max(highest, vertex);
        }
    }
}

} // namespace

Aabb cuboidAabb(const Transform& pose, const Vec3& halfExtents)
{
    const Vec3 halfWidths = rotatedHalfWidths(pose.orientation, halfExtents);
    return Aabb{pose.position - halfWidths, pose.position + halfWidths};
}

Aabb sweptCuboidAabb(const Transform& pose, const Vec3& halfExtents, const Vec3& velocity,
                     const Vec3& gravity, const Vec3& angularVelocity, Real dt, Real margin)
{
    // the centre's range over the step, axis by axis (10.2)
    Aabb centres;
    for (int axis = 0; axis < 3; ++axis) {
        ballisticRange(pose.position[axis], velocity[axis], gravity[axis], dt, centres.min[axis],
                       centres.max[axis]);
    }
    // a turn by at most angle |w| dt moves a body point at distance r by at most
    // min(angle, 2) r, and no body point is farther than the half diagonal from the centre (10.3)
    const Real halfDiagonal = glm::length(halfExtents);
    const Real angle = glm::length(angularVelocity) * dt;
    const Real reach = std::min(angle, 2.0) * halfDiagonal;
    const Vec3 halfWidths =
        glm::min(rotatedHalfWidths(pose.orientation, halfExtents) + Vec3(reach), Vec3(halfDiagonal));
    return Aabb{centres.min - halfWidths - Vec3(margin), centres.max + halfWidths + Vec3(margin)};
}

} // namespace tumble
