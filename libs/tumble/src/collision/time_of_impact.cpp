// Conservative advancement (Mirtich 1996) for the vertices of a cuboid against a plane.
#include "collision/time_of_impact.hpp"

#include "collision/collide_cuboid_plane.hpp"
#include "dynamics/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble {

namespace {

/// Enough advances for any sub-step the world takes; a search cut short returns a time before
/// the crossing, which is safe: the world simply takes another sub-step from there.
constexpr int kMaxAdvances = 200;

/// The pose after time s of the sub-step, and the angular velocity it has then.
Transform poseAndSpinAt(const SubstepMotion& motion, Real s, Vec3& angularVelocity)
{
    Transform pose;
    pose.position = positionAfter(motion.start.position, motion.velocityStart, motion.velocityEnd,
                                  motion.tau, s);
    pose.orientation = motion.start.orientation;
    angularVelocity = motion.angularVelocity;
    integrateRotation(pose.orientation, angularVelocity, motion.inertiaBody, s, motion.integrator);
    return pose;
}

} // namespace

Real freeClearance(const SubstepMotion& motion, const Vec3& halfExtents, const Plane& plane,
                   std::uint8_t touchingVertices, Real s)
{
    const std::array<Real, 8> heights = vertexHeights(poseAt(motion, s), halfExtents, plane);
    Real lowest = std::numeric_limits<Real>::infinity();
    for (int i = 0; i < 8; ++i) {
        if (((touchingVertices >> i) & 1u) == 0u) {
            lowest = std::min(lowest, heights[i]);
        }
    }
    return lowest;
}

Transform poseAt(const SubstepMotion& motion, Real s)
{
    Vec3 angularVelocity(0.0);
    return poseAndSpinAt(motion, s, angularVelocity);
}

namespace {

/// (4.4): how far from the body axis `axis` a vertex (at most `radius` from the centre) can be while a piece of the pose turns about
/// it: its distance from the axis, plus how far the pieces applied after it can carry it away
/// (turns about the axis itself keep the distance; the others, `otherRate` in all over the
/// sub-step, move a point by at most their angle times the half diagonal), and never more than
/// the half diagonal. A long thin body spinning fast about its long axis moves its vertices at
/// that spin times their small distance from the axis, not times the half diagonal.
Real axisReach(const Vec3& halfExtents, Real radius, int axis, Real otherRate, Real tau)
{
    Vec3 across = halfExtents;
    across[axis] = 0.0;
    return std::min(radius, glm::length(across) + radius * tau * otherRate);
}

/// (4.4) alone: each advance is the clearance above the aim over the bound on the approach speed.
Real linearAdvancement(const SubstepMotion& motion, const Vec3& halfExtents, const Plane& plane,
                       std::uint8_t touchingVertices, Real tolerance, Real approachBound,
                       int& advances)
{
    Real s = 0.0;
    for (int advance = 0; advance < kMaxAdvances; ++advance) {
        ++advances;
        const Real height = freeClearance(motion, halfExtents, plane, touchingVertices, s);
        if (height <= tolerance) {
            return s;
        }
        // Aim at half the tolerance so every advance gains at least tolerance / (2 bound).
        s += (height - 0.5 * tolerance) / approachBound;
        if (s >= motion.tau) {
            return motion.tau;
        }
    }
    return s;
}

/// The vertices' heights and their rates of change at time s of the sub-step.
struct VertexHeights {
    std::array<Real, 8> heights{};
    std::array<Real, 8> rates{};
};

VertexHeights vertexHeightsAndRates(const SubstepMotion& motion, const Vec3& halfExtents,
                                    const Plane& plane, Real s)
{
    Vec3 angularVelocity(0.0);
    const Transform pose = poseAndSpinAt(motion, s, angularVelocity);
    VertexHeights result;
    result.heights = vertexHeights(pose, halfExtents, plane);
    // dh_i/ds = n . v(s) + n . (w x R p_i) = n . v(s) + p_i . R^T (n x w); with n = +y,
    // n x w = (w_z, 0, -w_x).
    const Vec3 n = Plane::normal();
    const Vec3 velocity =
        motion.velocityStart + (s / motion.tau) * (motion.velocityEnd - motion.velocityStart);
    const Real centreRate = glm::dot(n, velocity);
    const Vec3 turn = glm::conjugate(pose.orientation) * glm::cross(n, angularVelocity);
    const Vec3 along = halfExtents * turn;
    for (int i = 0; i < 8; ++i) {
        // Vertex i has +e_k where bit k of i is set (cuboidVertices).
        result.rates[i] = centreRate + (((i & 1) ? along.x : -along.x) +
                                        ((i & 2) ? along.y : -along.y) +
                                        ((i & 4) ? along.z : -along.z));
    }
    return result;
}

/// (4.4a): the longest advance from height h (above the aim) at rate dh/ds = rate that no
/// height h + rate s - curvature s^2 / 2 can end below the aim: the positive root, in the form
/// without cancellation; infinity when the vertex never comes down.
Real quadraticAdvance(Real clearance, Real rate, Real curvature)
{
    return 2.0 * clearance / (-rate + std::sqrt(rate * rate + 2.0 * curvature * clearance));
}

} // namespace

Real timeOfImpact(const SubstepMotion& motion, const Vec3& halfExtents, const Plane& plane,
                  std::uint8_t touchingVertices, Real tolerance, int& advances)
{
    if (touchingVertices == 0xffu) {
        return motion.tau;
    }
    // (4.4): |dh/ds| <= max |v_n| + (turning rate) |r|max. The velocity is linear in s, so its
    // normal component is largest at an end; the turning rate is bounded by the integrator.
    const Vec3 n = Plane::normal();
    const Real normalSpeed = std::max(std::abs(glm::dot(n, motion.velocityStart)),
                                      std::abs(glm::dot(n, motion.velocityEnd)));
    const RotationBounds rates =
        rotationBounds(motion.start.orientation, motion.angularVelocity, motion.inertiaBody,
                       motion.tau, motion.integrator);
    const Real radius = glm::length(halfExtents);
    const Real approachBound =
        normalSpeed + rates.aboutAnyAxis * radius +
        rates.aboutNearAxis * axisReach(halfExtents, radius, rates.nearAxis,
                                        rates.aboutAnyAxis + rates.aboutFarAxis, motion.tau) +
        rates.aboutFarAxis * axisReach(halfExtents, radius, rates.farAxis,
                                       rates.aboutAnyAxis + rates.aboutNearAxis, motion.tau);
    if (approachBound == 0.0) {
        return motion.tau;
    }
    // (4.4a): where the pose is the exact flow, |d^2 h_i/ds^2| <= |n . a| + (|dw/ds| + |w|^2) r.
    const Real curvature =
        std::abs(glm::dot(n, motion.velocityEnd - motion.velocityStart)) / motion.tau +
        rates.curvature * radius;
    if (!std::isfinite(curvature)) {
        return linearAdvancement(motion, halfExtents, plane, touchingVertices, tolerance,
                                 approachBound, advances);
    }
    Real s = 0.0;
    for (int advance = 0; advance < kMaxAdvances; ++advance) {
        ++advances;
        const VertexHeights vertices = vertexHeightsAndRates(motion, halfExtents, plane, s);
        Real height = std::numeric_limits<Real>::infinity();
        for (int i = 0; i < 8; ++i) {
            if (((touchingVertices >> i) & 1u) == 0u) {
                height = std::min(height, vertices.heights[i]);
            }
        }
        if (height <= tolerance) {
            return s;
        }
        // Both the linear advance (4.4) and the least quadratic one (4.4a) end before any free
        // vertex reaches the aim, so the longer of the two does too.
        const Real aim = 0.5 * tolerance;
        Real quadratic = std::numeric_limits<Real>::infinity();
        for (int i = 0; i < 8; ++i) {
            if (((touchingVertices >> i) & 1u) == 0u) {
                quadratic = std::min(quadratic, quadraticAdvance(vertices.heights[i] - aim,
                                                                 vertices.rates[i], curvature));
            }
        }
        s += std::max((height - aim) / approachBound, quadratic);
        if (s >= motion.tau) {
            return motion.tau;
        }
    }
    return s;
}

} // namespace tumble
