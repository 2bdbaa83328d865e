// Solving for the single impulse (and point) that takes a body to a target velocity and spin.
#pragma once

#include "tumble/body.hpp"
#include "tumble/math.hpp"

namespace tumble {

/// Why a target could or could not be reached by one impulse.
enum class ImpulseTargetStatus {
    Reached,
    /// The velocity change is zero but the spin change is not: an impulse always moves the centre
    /// of mass, so no single impulse can only spin the body.
    SpinWithoutImpulse,
    /// The torque I dw needed is not perpendicular to the impulse m dv: r x J is always
    /// perpendicular to J.
    TorqueNotPerpendicular,
    /// The line of action needed misses the body, so no point of the body can take the impulse.
    LineMissesBody,
};

/// "reached" or a sentence saying why not.
const char* describe(ImpulseTargetStatus status);

struct ImpulseTarget {
    ImpulseTargetStatus status = ImpulseTargetStatus::Reached;
    /// The impulse J = m (v' - v), N s.
    Vec3 impulse{0.0};
    /// Point of application minus centre of mass, world axes, m; a point inside the body on the
    /// line of action (docs/physics/03-impulses.md, (3.4)).
    Vec3 offset{0.0};
};

/// Finds J and r with v + J/m = targetVelocity and w + I^-1 (r x J) = targetAngularVelocity.
/// `relativeTolerance` bounds |J . (I dw)| / (|J| |I dw|) for the perpendicularity test.
ImpulseTarget solveImpulseTarget(const Body& body, const Vec3& targetVelocity,
                                 const Vec3& targetAngularVelocity,
                                 Real relativeTolerance = 1e-9);

} // namespace tumble
