// World-level settings: the integrator, the contact response and every tunable of a World.
#pragma once

#include "tumble/math.hpp"

#include <cstdint>

namespace tumble {

/// How orientation and angular velocity advance in free flight.
enum class Integrator : std::uint8_t {
    /// Angular momentum is conserved exactly; the rotation is a symmetric splitting into exact
    /// rotations about the momentum and two body axes (docs/physics/02-integration.md). Translation under gravity
    /// is exact. The default.
    Exact,
    /// The handouts' update: R += dt [w]x R (re-orthonormalised), w held constant in flight.
    Handout,
};

/// How contact with the ground is resolved.
enum class ContactResponse : std::uint8_t {
    /// Impulses per touching vertex with accumulated clamping, a friction cone, restitution
    /// suppressed below a threshold, time of impact within the step, resting contact and rest
    /// detection (docs/physics/04..07). The default.
    Sequential,
    /// The handouts' model: after the step, move the body up so its lowest vertex lies on the
    /// plane and apply one impulse (with friction) at the average touching vertex.
    Average,
};

/// How the islands of touching bodies are solved (a body alone with the ground always takes the
/// exact path of docs/physics/04..07).
enum class ContactSolver : std::uint8_t {
    /// Impacts in time order, sub-steps cut at arrivals, resting contact solved to a tolerance
    /// (docs/physics/11-island-solver.md). The default.
    Exact,
    /// Fixed sub-steps of one soft, biased solve and one relax pass, restitution after them
    /// (docs/physics/12-soft-step.md): a fixed cost a step, for games and tools.
    Soft,
};

/// World-level tunables. Every default is the one a scenario file gets when it omits the key.
struct WorldSettings {
    /// Gravitational acceleration, m/s^2. Default (0, -9.81, 0).
    Vec3 gravity{0.0, -9.81, 0.0};
    /// Default Integrator::Exact.
    Integrator integrator = Integrator::Exact;
    /// Default ContactResponse::Sequential.
    ContactResponse response = ContactResponse::Sequential;
    /// A vertex closer to the plane than this counts as touching it, m. Default 1e-4.
    Real contactTolerance = 1e-4;
    /// Approach speeds below this get no restitution (a plastic impact), so a body can come to
    /// rest instead of bouncing forever, m/s. Default 0.05.
    Real restitutionThreshold = 0.05;
    /// Most Gauss-Seidel sweeps per contact solve; a solve stops earlier once it has converged.
    /// Default 256 (a solve on the verge of sliding converges slowly; see docs/validation.md).
    int solverIterations = 256;
    /// Default ContactSolver::Exact.
    ContactSolver solver = ContactSolver::Exact;
    /// The soft step's sub-steps per step. Default 4.
    int softSubsteps = 4;
    /// The soft step's contact stiffness as a frequency, Hz (twice this against static geometry,
    /// at most a quarter of the sub-step rate), and its damping ratio. Defaults 30 and 10.
    Real softContactHertz = 30.0;
    Real softDampingRatio = 10.0;
    /// Fastest the soft step pushes overlapping bodies apart, m/s. Default 3.
    Real softPushSpeed = 3.0;
    /// A body slower than these in contact with the ground for sleepTime is at rest. Defaults
    /// 1e-3 m/s, 1e-3 rad/s and 0.5 s.
    Real sleepLinearSpeed = 1e-3;
    Real sleepAngularSpeed = 1e-3;
    Real sleepTime = 0.5;
    /// Whether a body at rest is put to sleep (velocities zeroed, not integrated until woken by
    /// an impulse or a change). Default true.
    bool allowSleep = true;
    /// Whether step() keeps a ContactRecord of every contact solve (the contact ledger).
    /// Default false.
    bool recordContacts = false;
    /// Threads step() spreads its work over (1: the calling thread only; 0: one per core): the
    /// bodies alone and the islands of touching bodies, and within a large island the contacts
    /// of each colour of its sweeps. The results are identical whatever the number
    /// (docs/architecture.md, "Many bodies"; docs/physics/11-island-solver.md, (11.5c)). The
    /// threads of an island meet at a barrier after each colour: on cores shared with other
    /// work, OMP_WAIT_POLICY=passive keeps a waiting thread from spinning. Default 1.
    int threads = 1;
};

} // namespace tumble
