#include "tumble/scenario/runner.hpp"

#include "tumble/impulse_target.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace tumble::scenario {
namespace {

/// Steps of slack when counting steps for a duration (see stepCountFor).
constexpr Real kStepCountSlack = 1e-6;

/// Impulse times this close to a step boundary (as a fraction of dt) count as on the boundary,
/// so an `at` that is a multiple of dt does not split a step into a sliver and the rest.
constexpr Real kBoundaryFraction = 1e-9;

void appendEvents(const World& world, StepReport& report)
{
    const auto collisions = world.collisions();
    report.collisions.insert(report.collisions.end(), collisions.begin(), collisions.end());
    const auto restEvents = world.restEvents();
    report.restEvents.insert(report.restEvents.end(), restEvents.begin(), restEvents.end());
}

std::size_t bodyIndexByName(const Scenario& scenario, const ImpulseSpec& spec)
{
    const auto found = std::find_if(scenario.bodies.begin(), scenario.bodies.end(),
                                    [&](const BodySpec& body) { return body.name == spec.body; });
    if (found == scenario.bodies.end()) {
        throw ScenarioError(spec.where, spec.label + ".body", "no body named \"" + spec.body + "\"");
    }
    return static_cast<std::size_t>(found - scenario.bodies.begin());
}

} // namespace

long long stepCountFor(Real duration, Real dt)
{
    return static_cast<long long>(std::ceil(duration / dt - kStepCountSlack));
}

Real fixedStepLength(long long stepIndex, Real dt)
{
    return static_cast<Real>(stepIndex + 1) * dt - static_cast<Real>(stepIndex) * dt;
}

Runner::Runner(const Scenario& scenario) : m_scenario(scenario), m_built(buildWorld(m_scenario)) {}

const std::string& Runner::bodyName(std::size_t index) const
{
    return m_scenario.bodies.at(index).name;
}

std::size_t Runner::bodyIndex(BodyId id) const
{
    const auto found = std::find(m_built.bodies.begin(), m_built.bodies.end(), id);
    if (found == m_built.bodies.end()) {
        throw std::out_of_range("tumble::scenario::Runner::bodyIndex: not a body of this scenario");
    }
    return static_cast<std::size_t>(found - m_built.bodies.begin());
}

Real Runner::time() const
{
    return m_endedEarly ? *m_endedEarly : static_cast<Real>(m_stepCount) * m_scenario.dt;
}

StepReport Runner::step(Real until)
{
    const Real dt = m_scenario.dt;
    const Real tolerance = kBoundaryFraction * dt;
    const Real stepStart = time();
    Real stepEnd = static_cast<Real>(m_stepCount + 1) * dt;
    // a duration that is not a multiple of dt ends on a shortened step, as an impulse splits one
    if (until < stepEnd - tolerance && until > stepStart) {
        stepEnd = until;
        m_endedEarly = until;
    }
    StepReport report;

    // walk the impulses due before the end of this step, stepping up to each one in turn
    Real current = stepStart;
    while (m_nextImpulse < m_scenario.impulses.size() &&
           m_scenario.impulses[m_nextImpulse].at < stepEnd - tolerance) {
        const ImpulseSpec& spec = m_scenario.impulses[m_nextImpulse];
        if (spec.at > current + tolerance) {
            m_built.world.step(spec.at - current);
            appendEvents(m_built.world, report);
            current = spec.at;
        }

        const std::size_t index = bodyIndexByName(m_scenario, spec);
        const Body& body = m_built.world.body(m_built.bodies[index]);
        // a target is turned into one impulse at one point, or rejected with the reason
        Vec3 impulse = spec.impulse.value_or(Vec3(0.0));
        Vec3 offset = spec.offset.value_or(Vec3(0.0));
        if (spec.isTarget()) {
            const Vec3 targetAngularVelocity =
                spec.targetAngularVelocity.value_or(body.angularVelocity);
            const ImpulseTarget solved =
                solveImpulseTarget(body, *spec.targetVelocity, targetAngularVelocity);
            if (solved.status != ImpulseTargetStatus::Reached) {
                throw ScenarioError(spec.where, spec.label,
                                    std::string("target cannot be reached by one impulse: ") +
                                        describe(solved.status));
            }
            impulse = solved.impulse;
            offset = solved.offset;
        }
        AppliedImpulse applied = applyNow(index, impulse, offset, spec.label, spec.isTarget());
        applied.time = spec.at;
        report.impulses.push_back(applied);
        ++m_nextImpulse;
    }

    // the rest of the step (all of it when no impulse split it)
    m_built.world.step(stepEnd - current);
    appendEvents(m_built.world, report);
    ++m_stepCount;
    return report;
}

AppliedImpulse Runner::applyNow(std::size_t bodyIndex, const Vec3& impulse, const Vec3& offset,
                                const std::string& label, bool solvedFromTarget)
{
    const BodyId id = m_built.bodies.at(bodyIndex);
    const Body& before = m_built.world.body(id);
    AppliedImpulse applied{.time = time(),
                           .bodyIndex = bodyIndex,
                           .label = label,
                           .solvedFromTarget = solvedFromTarget,
                           .impulse = impulse,
                           .offset = offset,
                           .velocityBefore = before.linearVelocity,
                           .angularVelocityBefore = before.angularVelocity};
    m_built.world.applyImpulse(id, impulse, before.position + offset);
    const Body& after = m_built.world.body(id);
    applied.velocityAfter = after.linearVelocity;
    applied.angularVelocityAfter = after.angularVelocity;
    return applied;
}

} // namespace tumble::scenario
