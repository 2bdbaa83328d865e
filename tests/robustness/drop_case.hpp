// DropCase: one cuboid thrown at the ground plane with given parameters, stepped with a fixed dt
// while the invariants the robustness tests and the world-stepping fuzzer assert are measured
// (finite state, unit quaternion, energy never above the initial energy, no penetration).
#pragma once

#include "dynamics/integrator.hpp"
#include "tumble/body.hpp"
#include "tumble/shape.hpp"
#include "tumble/world.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble::robustness {

/// Energy may rise above the initial energy by at most this fraction of the energy scale
/// (kinetic energy plus m |g| times the drop height and the body's diagonal), for rounding and
/// settling onto the plane ...
inline constexpr Real kEnergyTolerance = 1e-6;
/// ... plus the exact rotation's energy error: (2.7) conserves angular momentum exactly but the
/// energy only to O((|w| dt)^2), within the bound (2.7b) of rotationEnergyErrorBound, taken at its
/// largest over the steps (docs/physics/02-integration.md). For the handout integrator, whose
/// energy is not bounded, the fuzzer does not check energy.
/// After every step no vertex may be deeper below the plane than this fraction of the length
/// scale (the body's diagonal plus its distance from the origin): the position correction (4.5)
/// leaves only rounding (docs/physics/04-detection.md).
inline constexpr Real kPenetrationTolerance = 1e-12;
/// The orientation is renormalised every step; |q| stays 1 to rounding.
inline constexpr Real kQuaternionTolerance = 1e-12;

struct DropCase {
    Real mass = 1.0;
    /// Full extents, m.
    Vec3 size{2.0, 2.0, 2.0};
    Quat orientation{1.0, 0.0, 0.0, 0.0};
    /// Height of the lowest vertex above the ground at the start, m.
    Real height = 1.0;
    Vec3 velocity{0.0};
    Vec3 angularVelocity{0.0};
    Real restitution = 0.6;
    Real friction = 0.5;
    Real dt = 1.0 / 240.0;
    long long steps = 240;
    Integrator integrator = Integrator::Exact;
    ContactResponse response = ContactResponse::Sequential;
    bool allowSleep = true;
};

struct DropOutcome {
    /// Steps actually taken (fewer than asked when the state stopped being finite).
    long long steps = 0;
    bool finite = true;
    /// Kinetic plus potential energy (zero at the ground) at the start, J.
    Real initialEnergy = 0.0;
    /// Energy scale of the case: initial kinetic energy plus m |g| (height + diagonal), J.
    Real energyScale = 0.0;
    /// Largest (energy - initial energy) / energyScale after any step.
    Real maxRelativeEnergyGain = -std::numeric_limits<Real>::infinity();
    /// Length scale: diagonal plus distance of the centre from the origin at the start, m.
    Real lengthScale = 0.0;
    /// Deepest vertex below the plane after any step, m (0 when none went below).
    Real maxPenetration = 0.0;
    /// Largest |w| dt at the end of any step, rad.
    Real maxTurnPerStep = 0.0;
    /// Largest bound (2.7b) on the rotation's energy error at the end of any step, J.
    Real maxRotationEnergyError = 0.0;
    /// Largest | |q| - 1 | after any step.
    Real maxQuaternionError = 0.0;
    /// Impacts reported, the fastest approach speed of one, and the fastest upward speed of the
    /// centre of mass just after an impact step, m/s.
    int impacts = 0;
    Real fastestApproach = 0.0;
    Real fastestRebound = 0.0;
    /// Lowest height of the centre of mass above the ground after any step, m.
    Real lowestCentre = std::numeric_limits<Real>::infinity();
    /// Whether the body was asleep at the end.
    bool asleep = false;

    [[nodiscard]] Real energyTolerance() const
    {
        return kEnergyTolerance + maxRotationEnergyError / energyScale;
    }
    [[nodiscard]] bool energyBounded() const { return maxRelativeEnergyGain <= energyTolerance(); }
    [[nodiscard]] bool penetrationBounded() const
    {
        return maxPenetration <= kPenetrationTolerance * lengthScale;
    }
    [[nodiscard]] bool quaternionUnit() const { return maxQuaternionError <= kQuaternionTolerance; }
};

inline Real lowestVertexHeight(const Body& body)
{
    Real lowest = std::numeric_limits<Real>::infinity();
    for (const Vec3& vertex : cuboidVertices(body.shape.halfExtents())) {
        lowest = std::min(lowest, body.worldPoint(vertex).y);
    }
    return lowest;
}

inline bool isFiniteState(const Body& body)
{
    return isFinite(body.position) && isFinite(body.orientation) &&
           isFinite(body.linearVelocity) && isFinite(body.angularVelocity);
}

/// A world with the ground y = 0 and the case's body, placed so its lowest vertex is at
/// `height`.
inline World makeDropWorld(const DropCase& drop, BodyId& id)
{
    WorldSettings settings;
    settings.integrator = drop.integrator;
    settings.response = drop.response;
    settings.allowSleep = drop.allowSleep;
    World world(settings);
    world.setGround(Plane{});
    BodyDef def;
    def.mass = drop.mass;
    def.shape.size = drop.size;
    def.orientation = glm::normalize(drop.orientation);
    def.linearVelocity = drop.velocity;
    def.angularVelocity = drop.angularVelocity;
    def.material.restitution = drop.restitution;
    def.material.friction = drop.friction;
    id = world.createBody(def);
    const Real lowest = lowestVertexHeight(world.body(id));
    world.setTransform(id, Vec3(0.0, drop.height - lowest, 0.0), def.orientation);
    return world;
}

/// Steps the case and measures every invariant after every step.
inline DropOutcome runDrop(const DropCase& drop)
{
    BodyId id;
    World world = makeDropWorld(drop, id);
    const Vec3 gravity = world.settings().gravity;
    const auto energy = [&](const Body& body) {
        return body.kineticEnergy() + body.potentialEnergy(gravity);
    };
    DropOutcome outcome;
    const Body& start = world.body(id);
    const Real diagonal = glm::length(drop.size);
    outcome.initialEnergy = energy(start);
    outcome.energyScale = start.kineticEnergy() +
                          start.mass * glm::length(gravity) * (std::max(drop.height, 0.0) + diagonal);
    outcome.lengthScale = diagonal + glm::length(start.position);
    outcome.maxTurnPerStep = glm::length(start.angularVelocity) * drop.dt;
    const auto rotationError = [&](const Body& body) {
        return rotationEnergyErrorBound(body.orientation, body.angularVelocity,
                                        body.inertiaBody(), drop.dt);
    };
    outcome.maxRotationEnergyError = rotationError(start);
    for (long long step = 0; step < drop.steps; ++step) {
        world.step(drop.dt);
        outcome.steps = step + 1;
        const Body& body = world.body(id);
        if (!isFiniteState(body)) {
            outcome.finite = false;
            break;
        }
        outcome.maxRelativeEnergyGain =
            std::max(outcome.maxRelativeEnergyGain,
                     (energy(body) - outcome.initialEnergy) / outcome.energyScale);
        outcome.maxPenetration = std::max(outcome.maxPenetration, -lowestVertexHeight(body));
        outcome.maxTurnPerStep =
            std::max(outcome.maxTurnPerStep, glm::length(body.angularVelocity) * drop.dt);
        outcome.maxRotationEnergyError =
            std::max(outcome.maxRotationEnergyError, rotationError(body));
        outcome.maxQuaternionError =
            std::max(outcome.maxQuaternionError, std::abs(glm::length(body.orientation) - 1.0));
        outcome.lowestCentre = std::min(outcome.lowestCentre, body.position.y);
        for (const CollisionEvent& event : world.collisions()) {
            ++outcome.impacts;
            outcome.fastestApproach = std::max(outcome.fastestApproach, event.approachSpeed);
        }
        if (!world.collisions().empty()) {
            outcome.fastestRebound = std::max(outcome.fastestRebound, body.linearVelocity.y);
        }
    }
    outcome.asleep = world.body(id).asleep;
    return outcome;
}

} // namespace tumble::robustness
