// When the points of an island still apart arrive within a sub-step (docs/physics/11-island-
// solver.md, (11.8), (11.8a)).
#pragma once

#include "dynamics/contact_constraint.hpp"

#include <span>
#include <vector>

namespace tumble {

/// The motion of a point's gap over a sub-step, g(s) = g + v0 s + a s^2 / 2.
struct GapMotion {
    /// Relative normal velocity at the start of the sub-step, m/s.
    Real startVelocity = 0.0;
    /// Relative normal acceleration from everything but the speculative impulses, m/s^2.
    Real acceleration = 0.0;
};

/// (11.8): each constraint's gap motion over a sub-step of length tau. `freeBodies` hold the
/// end velocities of a solve of the points in contact alone (gravity and the support of bodies
/// held by others, not the speculative impulses); `velocityStart` and `angularVelocityStart` the
/// island's bodies' velocities at the start; the static solver body (the last) has none.
void gapMotions(std::span<const ContactConstraint> constraints,
                std::span<const SolverBody> freeBodies, std::span<const Vec3> velocityStart,
                std::span<const Vec3> angularVelocityStart, Real tau,
                std::vector<GapMotion>& motions);

/// Whether the solve stopped a point still apart that bounces (e > 0): only then can a sub-step
/// be cut (11.8).
[[nodiscard]] bool anyBouncingArrival(std::span<const ContactConstraint> constraints,
                                      Real touchingGap, int threads = 1);

/// (11.8): the earliest arrival within tau of a point still apart whose speculative target
/// bound, that bounces (e > 0) and approaches faster than the restitution threshold; tau when
/// there is none.
[[nodiscard]] Real earliestArrival(std::span<const ContactConstraint> constraints,
                                   std::span<const GapMotion> motions, Real tau, Real touchingGap,
                                   Real restitutionThreshold);

/// (11.8a): a point whose gap motion closes its gap at the end of a sub-step of length tau (the
/// sub-step was cut at its arrival) may reach its free-flight velocity there, not only its mean
/// velocity -gap/tau: its target becomes the lower of the two.
void keepExactArrivals(std::span<ContactConstraint> constraints, std::span<const GapMotion> motions,
                       Real tau, Real touchingGap, int threads = 1);

} // namespace tumble
