// The single impulse and point that take a body to a target velocity and angular velocity
// (docs/physics/03-impulses.md, (3.3)-(3.5)).
#include "tumble/impulse_target.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble {

const char* describe(ImpulseTargetStatus status)
{
    switch (status) {
    case ImpulseTargetStatus::Reached: return "reached";
    case ImpulseTargetStatus::SpinWithoutImpulse:
        return "the angular velocity changes but the velocity does not; an impulse always changes "
               "the velocity of the centre of mass";
    case ImpulseTargetStatus::TorqueNotPerpendicular:
        return "the angular impulse I*dw needed is not perpendicular to the impulse m*dv, but "
               "r x J always is";
    case ImpulseTargetStatus::LineMissesBody:
        return "the line of action the impulse needs does not pass through the body";
    }
    return "?";
}

namespace {

/// The parameter range [sMin, sMax] for which origin + s * direction lies in the box
/// |p_i| <= halfExtents_i (slab method); empty when sMin > sMax.
void clipLineToBox(const Vec3& origin, const Vec3& direction, const Vec3& halfExtents, Real& sMin,
                   Real& sMax)
{
    sMin = -std::numeric_limits<Real>::infinity();
    sMax = std::numeric_limits<Real>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        // A hair of slack so a line along a face is not lost to rounding.
        const Real half = halfExtents[axis] * (1.0 + 1e-12);
        if (std::abs(direction[axis]) < 1e-300) {
            if (std::abs(origin[axis]) > half) {
                sMin = 1.0;
                sMax = 0.0;
                return;
            }
            continue;
        }
        Real s0 = (-half - origin[axis]) / direction[axis];
        Real s1 = (half - origin[axis]) / direction[axis];
        if (s0 > s1) {
            std::swap(s0, s1);
        }
        sMin = std::max(sMin, s0);
        sMax = std::min(sMax, s1);
    }
}

} // namespace

ImpulseTarget solveImpulseTarget(const Body& body, const Vec3& targetVelocity,
                                 const Vec3& targetAngularVelocity, Real relativeTolerance)
{
    ImpulseTarget result;
    // (3.3): the impulse is fixed by the velocity change, the angular impulse by the spin change.
    const Vec3 impulse = body.mass * (targetVelocity - body.linearVelocity);
    const Vec3 angularImpulse = body.inertiaWorld() * (targetAngularVelocity - body.angularVelocity);
    const Real impulseLength = glm::length(impulse);
    const Real angularLength = glm::length(angularImpulse);
    const Real velocityScale =
        std::max({1.0, glm::length(targetVelocity), glm::length(body.linearVelocity)});
    const Real spinScale =
        std::max({1.0, glm::length(targetAngularVelocity), glm::length(body.angularVelocity)});

    const bool noImpulse = impulseLength <= 1e-12 * body.mass * velocityScale;
    const bool noAngularImpulse =
        angularLength <= 1e-12 * glm::length(body.inertiaBody()) * spinScale;
    if (noImpulse) {
        result.status = noAngularImpulse ? ImpulseTargetStatus::Reached
                                         : ImpulseTargetStatus::SpinWithoutImpulse;
        return result;
    }
    result.impulse = impulse;
    if (noAngularImpulse) {
        return result; // through the centre of mass: offset 0
    }
    if (std::abs(glm::dot(impulse, angularImpulse)) >
        relativeTolerance * impulseLength * angularLength) {
        result.status = ImpulseTargetStatus::TorqueNotPerpendicular;
        return result;
    }
    // (3.4): r0 = J x (I dw) / |J|^2 solves r x J = I dw; so does r0 + s J for every s (3.5).
    const Vec3 closestOffset = glm::cross(impulse, angularImpulse) / (impulseLength * impulseLength);
    const Quat toBody = glm::conjugate(body.orientation);
    const Vec3 direction = impulse / impulseLength;
    Real sMin = 0.0;
    Real sMax = 0.0;
    clipLineToBox(toBody * closestOffset, toBody * direction, body.shape.halfExtents(), sMin, sMax);
    if (sMin > sMax) {
        result.status = ImpulseTargetStatus::LineMissesBody;
        return result;
    }
    // The point of the body on the line nearest the centre of mass.
    result.offset = closestOffset + std::clamp(0.0, sMin, sMax) * direction;
    return result;
}

} // namespace tumble
