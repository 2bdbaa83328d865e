// Runner: steps a scenario's World with its fixed dt and applies the scheduled impulses on time.
#pragma once

#include "tumble/contact.hpp"
#include "tumble/math.hpp"
#include "tumble/scenario/scenario.hpp"
#include "tumble/world.hpp"

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace tumble::scenario {

/// A scheduled impulse as it was applied.
struct AppliedImpulse {
    Real time = 0.0;
    std::size_t bodyIndex = 0;
    /// The entry's label ("impulse[0]").
    std::string label;
    bool solvedFromTarget = false;
    Vec3 impulse{0.0};
    Vec3 offset{0.0};
    Vec3 velocityBefore{0.0};
    Vec3 angularVelocityBefore{0.0};
    Vec3 velocityAfter{0.0};
    Vec3 angularVelocityAfter{0.0};
};

/// What happened during one Runner::step.
struct StepReport {
    std::vector<AppliedImpulse> impulses;
    std::vector<CollisionEvent> collisions;
    std::vector<RestEvent> restEvents;
};

/// Number of fixed steps of length dt after which a run has reached `duration`: ceil(duration /
/// dt) less a slack of 1e-6 steps, so a duration that is a whole number of steps up to rounding
/// (10 / (1/240) = 2400.0000000004) does not get one step more.
long long stepCountFor(Real duration, Real dt);

/// The length of fixed step `stepIndex` (0-based) that Runner::step gives World::step when no
/// impulse splits it: (stepIndex + 1) dt - stepIndex dt, which differs from dt in the last bits.
/// Anything that must reproduce a run bit for bit steps with these lengths.
Real fixedStepLength(long long stepIndex, Real dt);

/// Owns the World built from a scenario and advances it one fixed step at a time. An impulse
/// whose time falls inside a step splits that step, so it acts at exactly its `at`.
class Runner {
public:
    explicit Runner(const Scenario& scenario);

    [[nodiscard]] const Scenario& scenario() const { return m_scenario; }
    [[nodiscard]] World& world() { return m_built.world; }
    [[nodiscard]] const World& world() const { return m_built.world; }
    [[nodiscard]] const std::vector<BodyId>& bodies() const { return m_built.bodies; }
    [[nodiscard]] const std::string& bodyName(std::size_t index) const;
    /// Index in scenario().bodies of the body with this id.
    [[nodiscard]] std::size_t bodyIndex(BodyId id) const;

    /// Number of fixed steps taken; time() is stepCount() * dt, not a running sum, or the end
    /// time of a step that `until` shortened.
    [[nodiscard]] long long stepCount() const { return m_stepCount; }
    [[nodiscard]] Real time() const;
    /// Advances by the scenario's dt, or to `until` when that comes first (more than 1e-9 dt
    /// before the step's end): a run whose duration is not a multiple of dt ends at the duration,
    /// and such a shortened step must be the last. Throws ScenarioError when a target impulse is
    /// unreachable.
    StepReport step(Real until = std::numeric_limits<Real>::infinity());
    /// Applies `impulse` now to body `bodyIndex` at `offset` from its centre of mass and returns
    /// the record of it, velocities before and after (a scheduled entry's, or the impulse tool's).
    AppliedImpulse applyNow(std::size_t bodyIndex, const Vec3& impulse, const Vec3& offset,
                            const std::string& label, bool solvedFromTarget);

private:
    Scenario m_scenario;
    BuiltWorld m_built;
    std::size_t m_nextImpulse = 0;
    long long m_stepCount = 0;
    /// Set when `until` shortened the last step: the time it ended at.
    std::optional<Real> m_endedEarly;
};

} // namespace tumble::scenario
