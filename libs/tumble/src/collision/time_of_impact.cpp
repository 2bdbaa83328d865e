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
    Transform pose;
    pose.position = positionAfter(motion.start.position, motion.velocityStart, motion.velocityEnd,
                                  motion.tau, s);
    pose.orientation = motion.start.orientation;
    Vec3 angularVelocity = motion.angularVelocity;
    integrateRotation(pose.orientation, angularVelocity, motion.inertiaBody, s, motion.integrator);
    return pose;
}

Real timeOfImpact(const SubstepMotion& motion, const Vec3& halfExtents, const Plane& plane,
                  std::uint8_t touchingVertices, Real tolerance)
{
    if (touchingVertices == 0xffu) {
        return motion.tau;
    }
    // (4.4): |dh/ds| <= max |v_n| + (turning rate) |r|max. The velocity is linear in s, so its
    // normal component is largest at an end; the turning rate is bounded by the integrator.
    const Vec3 n = Plane::normal();
    const Real normalSpeed = std::max(std::abs(glm::dot(n, motion.velocityStart)),
                                      std::abs(glm::dot(n, motion.velocityEnd)));
    const Real spin = rotationRateBound(motion.start.orientation, motion.angularVelocity,
                                        motion.inertiaBody, motion.tau, motion.integrator);
    const Real approachBound = normalSpeed + spin * glm::length(halfExtents);
    if (approachBound == 0.0) {
        return motion.tau;
    }

    Real s = 0.0;
    for (int advance = 0; advance < kMaxAdvances; ++advance) {
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

} // namespace tumble
