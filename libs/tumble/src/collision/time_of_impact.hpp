// When, within a sub-step, a vertex not yet touching the ground first reaches it
// (conservative advancement, docs/physics/04-detection.md, (4.3)-(4.4)).
#pragma once

#include "tumble/math.hpp"
#include "tumble/shape.hpp"
#include "tumble/settings.hpp"

#include <cstdint>

namespace tumble {

/// How a body moves during a sub-step of length tau: the centre-of-mass velocity changes
/// uniformly from velocityStart to velocityEnd, and the body rotates freely from angularVelocity.
struct SubstepMotion {
    Transform start{};
    Vec3 velocityStart{0.0};
    Vec3 velocityEnd{0.0};
    Vec3 angularVelocity{0.0};
    Vec3 inertiaBody{1.0};
    Real tau = 0.0;
    Integrator integrator = Integrator::Exact;
};

/// The pose after time s (0 <= s <= tau) of the sub-step.
Transform poseAt(const SubstepMotion& motion, Real s);

/// Height above the plane of the lowest vertex outside `touchingVertices` (bit i = vertex i) at
/// time s of the sub-step; infinity when every vertex is touching.
Real freeClearance(const SubstepMotion& motion, const Vec3& halfExtents, const Plane& plane,
                   std::uint8_t touchingVertices, Real s);

/// The earliest s in (0, tau] at which a vertex outside `touchingVertices` (bit i = vertex i)
/// comes within `tolerance` of the plane, or tau when none does. Never steps past a crossing:
/// each advance is the remaining clearance over a bound on the approach speed (4.4). Adds the
/// advances it took (one pose each) to `advances`.
Real timeOfImpact(const SubstepMotion& motion, const Vec3& halfExtents, const Plane& plane,
                  std::uint8_t touchingVertices, Real tolerance, int& advances);

} // namespace tumble
