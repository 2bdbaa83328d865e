// Impulses at the touching vertices of one cuboid: impacts with restitution, resting contact and
// Coulomb friction (docs/physics/05-normal-impulse.md, 06-friction.md).
#pragma once

#include "tumble/body.hpp"
#include "tumble/contact.hpp"

namespace tumble {

struct ContactSolveSettings {
    /// Approach speeds below this get no restitution, m/s.
    Real restitutionThreshold = 0.05;
    /// Most Gauss-Seidel sweeps.
    int iterations = 256;
};

/// Work done on the body by contact impulses, J: the sum over the points of P . (u_before +
/// u_after) / 2 with P a point's total impulse and u its velocity (08-energy-ledger.md, (8.2)).
/// Negative: energy removed.
struct ContactWork {
    Real normal = 0.0;
    Real friction = 0.0;
    /// Energy received from other bodies (8.4); zero against static geometry.
    Real exchanged = 0.0;
};

/// What an impact did to the body.
struct ImpactOutcome {
    /// Fastest approach of a touching vertex before the impact (a positive speed), m/s.
    Real approachSpeed = 0.0;
    bool restitutionApplied = false;
    /// The coefficient of restitution the impact used.
    Real restitution = 0.0;
    Real kineticEnergyBefore = 0.0;
    Real kineticEnergyAfter = 0.0;
    /// Sums of the normal and the friction impulses, world frame, N s.
    Vec3 normalImpulse{0.0};
    Vec3 frictionImpulse{0.0};
    ContactWork work{};
};

/// Fastest approach speed of the manifold's vertices towards the plane (0 when all separate).
Real approachSpeed(const Body& body, const ContactManifold& manifold);

/// An instantaneous impact: sequential impulses with accumulated clamping reach the Newton
/// restitution target (5.3) at every approaching vertex, with friction limited to the Coulomb
/// cone (6.2). Never lets the kinetic energy grow (5.6). Writes the impulses into the manifold.
ImpactOutcome resolveImpact(Body& body, ContactManifold& manifold,
                            const ContactSolveSettings& settings);

/// A sub-step of length tau: adds `gravityImpulsePerMass` (g tau) to the velocity, then solves
/// resting contact with no restitution (5.5): a vertex on the plane may not approach it, and one
/// still h above it may approach at most at h / tau, so it comes down onto the plane instead of
/// hovering (5.9). Static or kinetic friction is chosen from the sliding before gravity acts.
/// The solve starts from the impulses in `warmStart` (scaled to tau, clamped to the cone) for the
/// vertices it lists (5.10).
ContactWork solveRestingContact(Body& body, ContactManifold& manifold,
                                const Vec3& gravityImpulsePerMass, Real tau,
                                const ContactSolveSettings& settings,
                                const WarmStartCache& warmStart);

/// The cache for the next step from a published resting solve of length tau.
WarmStartCache makeWarmStart(const ContactManifold& manifold, Real tau);

/// The handouts' response (5.7): one impulse at the average touching vertex with restitution,
/// and a Coulomb friction impulse opposing the sliding there; approachSpeed is measured at the
/// average point. Nothing happens when that point separates.
ImpactOutcome resolveAverageContact(Body& body, ContactManifold& manifold,
                                    const ContactSolveSettings& settings);

} // namespace tumble
