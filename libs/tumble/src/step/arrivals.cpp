// Arrival times of the points of an island still apart (docs/physics/11-island-solver.md).
#include "step/arrivals.hpp"

#include "parallel_for.hpp"

#include <algorithm>
#include <cmath>

namespace tumble {

namespace {

/// A point whose free-flight gap at the end of a sub-step is within this share of its gap at the
/// start arrives at the end: the rounding of the arrival time's root.
constexpr Real kArrivalMatch = 1e-9;

struct BodyVelocity {
    Vec3 linear{0.0};
    Vec3 angular{0.0};

    [[nodiscard]] Vec3 at(const Vec3& offset) const { return linear + glm::cross(angular, offset); }
};

/// Normal velocity of B's point relative to A's.
Real normalVelocity(const ContactConstraint& c, std::span<const BodyVelocity> velocities)
{
    return glm::dot(c.normal, velocities[c.bodyB].at(c.offsetB) - velocities[c.bodyA].at(c.offsetA));
}

} // namespace

void gapMotions(std::span<const ContactConstraint> constraints,
                std::span<const SolverBody> freeBodies, std::span<const Vec3> velocityStart,
                std::span<const Vec3> angularVelocityStart, Real tau,
                std::vector<GapMotion>& motions)
{
    std::vector<BodyVelocity> free(freeBodies.size());
    std::vector<BodyVelocity> start(freeBodies.size());
    for (std::size_t i = 0; i < freeBodies.size(); ++i) {
        free[i] = {freeBodies[i].linearVelocity, freeBodies[i].angularVelocity};
        if (i < velocityStart.size()) {
            start[i] = {velocityStart[i], angularVelocityStart[i]};
        }
    }
    motions.resize(constraints.size());
    for (std::size_t k = 0; k < constraints.size(); ++k) {
        const Real v0 = normalVelocity(constraints[k], start);
        motions[k] = {v0, (normalVelocity(constraints[k], free) - v0) / tau};
    }
}

bool anyBouncingArrival(std::span<const ContactConstraint> constraints, Real touchingGap,
                        int threads)
{
    return parallelAnyOf(constraints.size(), threads, [&](std::size_t k) {
        const ContactConstraint& c = constraints[k];
        return c.separation > touchingGap && c.normalImpulse > 0.0 && c.restitution > 0.0;
    });
}

Real earliestArrival(std::span<const ContactConstraint> constraints,
                     std::span<const GapMotion> motions, Real tau, Real touchingGap,
                     Real restitutionThreshold)
{
    Real arrival = tau;
    for (std::size_t k = 0; k < constraints.size(); ++k) {
        const ContactConstraint& c = constraints[k];
        if (c.separation <= touchingGap || c.normalImpulse <= 0.0 || c.restitution <= 0.0) {
            continue;
        }
        // the first root of g + v0 s + a s^2 / 2 = 0, s* = 2 g / (-v0 + sqrt(v0^2 - 2 a g))
        const Real v0 = motions[k].startVelocity;
        const Real a = motions[k].acceleration;
        if (-v0 - 0.5 * a * tau <= restitutionThreshold) {
            continue;
        }
        const Real root = std::sqrt(std::max(0.0, v0 * v0 - 2.0 * a * c.separation));
        if (-v0 + root > 0.0) {
            arrival = std::min(arrival, 2.0 * c.separation / (-v0 + root));
        }
    }
    return arrival;
}

void keepExactArrivals(std::span<ContactConstraint> constraints, std::span<const GapMotion> motions,
                       Real tau, Real touchingGap, int threads)
{
    // each point writes only its own target
    parallelFor(std::min(constraints.size(), motions.size()), threads, [&](std::size_t k) {
        ContactConstraint& c = constraints[k];
        if (c.separation <= touchingGap) {
            return;
        }
        const Real v0 = motions[k].startVelocity;
        const Real a = motions[k].acceleration;
        const Real endGap = c.separation + v0 * tau + 0.5 * a * tau * tau;
        if (std::abs(endGap) <= kArrivalMatch * c.separation) {
            // the free-flight end velocity v0 + a tau: the gap closes exactly as the sub-step ends
            c.targetNormalVelocity = std::min(c.targetNormalVelocity, v0 + a * tau);
        }
    });
}

} // namespace tumble
