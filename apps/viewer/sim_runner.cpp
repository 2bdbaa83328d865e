#include "viewer/sim_runner.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

namespace tumble::viewer {
namespace {

/// Slack when counting steps to a time, as `tumble run` counts them, so a time that is a whole
/// number of steps up to rounding does not get one step more.
constexpr Real kStepCountSlack = 1e-6;

int maxStepsPerFrame(Real dt)
{
    return std::max(1, static_cast<int>(std::ceil(SimRunner::kMaxSecondsPerFrame / dt)));
}

bool isFiniteBody(const Body& body)
{
    return isFinite(body.position) && isFinite(body.orientation) &&
           isFinite(body.linearVelocity) && isFinite(body.angularVelocity);
}

} // namespace

SimRunner::SimRunner(std::filesystem::path file, std::vector<std::string> overrides)
    : m_file(std::move(file)), m_overrides(std::move(overrides)),
      m_scenario(scenario::loadScenario(m_file, m_overrides)),
      m_accumulator(m_scenario.dt, maxStepsPerFrame(m_scenario.dt))
{
    start(m_scenario);
}

SimRunner::~SimRunner() = default;

const Body& SimRunner::body(std::size_t index) const { return world().body(idOf(index)); }

bool SimRunner::open(const std::filesystem::path& file)
{
    try {
        scenario::Scenario loaded = scenario::loadScenario(file);
        m_file = file;
        m_overrides.clear();
        ++m_scenarioSerial;
        start(std::move(loaded));
        return true;
    } catch (const scenario::ScenarioError& error) {
        m_error = error.what();
        return false;
    }
}

bool SimRunner::reload()
{
    try {
        start(scenario::loadScenario(m_file, m_overrides));
        return true;
    } catch (const scenario::ScenarioError& error) {
        m_error = error.what();
        return false;
    }
}

void SimRunner::reset() { start(m_scenario); }

void SimRunner::start(scenario::Scenario scenario)
{
    m_scenario = std::move(scenario);
    // the contact ledger's records are where the view finds contacts between bodies
    m_scenario.settings.recordContacts = true;
    m_runner = std::make_unique<scenario::Runner>(m_scenario);
    m_lastCollisions.assign(m_runner->bodies().size(), std::nullopt);
    m_accumulator = FixedStepAccumulator(m_scenario.dt, maxStepsPerFrame(m_scenario.dt));
    m_error.clear();
    if (m_resetListener) {
        m_resetListener(*m_runner);
    }
}

void SimRunner::setPaused(bool paused)
{
    m_paused = paused;
    m_accumulator.reset();
}

void SimRunner::stepOnce()
{
    setPaused(true);
    stepChecked();
}

void SimRunner::setTimeScale(double scale)
{
    m_timeScale = std::clamp(scale, kMinTimeScale, kMaxTimeScale);
}

int SimRunner::advance(double frameSeconds)
{
    if (m_paused) {
        return 0;
    }
    const int due = m_accumulator.advance(frameSeconds, m_timeScale);
    int taken = 0;
    while (taken < due && !m_paused && stepChecked()) {
        ++taken;
    }
    return taken;
}

void SimRunner::advanceTo(Real time)
{
    const auto target = static_cast<long long>(std::ceil(time / m_scenario.dt - kStepCountSlack));
    while (m_runner->stepCount() < target && stepChecked()) {
    }
}

bool SimRunner::stepChecked()
{
    // a target impulse that cannot be reached, or a state gone non-finite, stops the run
    scenario::StepReport report;
    try {
        report = m_runner->step();
    } catch (const scenario::ScenarioError& error) {
        m_error = error.what();
        m_paused = true;
        return false;
    }
    record(report);
    for (std::size_t i = 0; i < bodyCount(); ++i) {
        if (!isFiniteBody(body(i))) {
            std::ostringstream message;
            message << "the state of body " << m_runner->bodyName(i) << " is not finite at t = "
                    << time() << " s";
            m_error = message.str();
            m_paused = true;
            return false;
        }
    }
    return true;
}

void SimRunner::record(const scenario::StepReport& report)
{
    for (const CollisionEvent& collision : report.collisions) {
        m_lastCollisions[m_runner->bodyIndex(collision.manifold.body)] = collision;
    }
    if (m_stepListener) {
        m_stepListener(*m_runner, report);
    }
}

BodyId SimRunner::idOf(std::size_t body) const { return m_runner->bodies().at(body); }

World& SimRunner::mutableWorld() { return m_runner->world(); }

void SimRunner::setGravity(const Vec3& gravity)
{
    mutableWorld().setGravity(gravity);
    m_scenario.settings.gravity = gravity;
}

void SimRunner::setIntegrator(Integrator integrator)
{
    mutableWorld().setIntegrator(integrator);
    m_scenario.settings.integrator = integrator;
}

void SimRunner::setResponse(ContactResponse response)
{
    mutableWorld().setResponse(response);
    m_scenario.settings.response = response;
}

void SimRunner::setDt(Real dt) { m_scenario.dt = dt; }

void SimRunner::setMass(std::size_t body, Real mass)
{
    mutableWorld().setMass(idOf(body), mass);
    m_scenario.bodies.at(body).def.mass = mass;
}

void SimRunner::setSize(std::size_t body, const Vec3& size)
{
    mutableWorld().setSize(idOf(body), size);
    m_scenario.bodies.at(body).def.shape.size = size;
}

void SimRunner::setMaterial(std::size_t body, const Material& material)
{
    mutableWorld().setMaterial(idOf(body), material);
    m_scenario.bodies.at(body).def.material = material;
}

void SimRunner::setVelocities(std::size_t body, const Vec3& velocity, const Vec3& angularVelocity)
{
    mutableWorld().setLinearVelocity(idOf(body), velocity);
    mutableWorld().setAngularVelocity(idOf(body), angularVelocity);
}

void SimRunner::applyImpulse(std::size_t body, const Vec3& impulse, const Vec3& offset,
                             const std::string& label)
{
    applyReported(body, impulse, offset, label, false);
}

void SimRunner::applyReported(std::size_t body, const Vec3& impulse, const Vec3& offset,
                              const std::string& label, bool solvedFromTarget)
{
    const scenario::AppliedImpulse applied =
        m_runner->applyNow(body, impulse, offset, label, solvedFromTarget);
    m_error.clear();
    if (m_stepListener) {
        m_stepListener(*m_runner, scenario::StepReport{.impulses = {applied}});
    }
}

ImpulseTarget SimRunner::applyTarget(std::size_t body, const Vec3& targetVelocity,
                                     const std::optional<Vec3>& targetAngularVelocity,
                                     const std::string& label)
{
    const Body& state = this->body(body);
    const ImpulseTarget solved = solveImpulseTarget(
        state, targetVelocity, targetAngularVelocity.value_or(state.angularVelocity));
    if (solved.status != ImpulseTargetStatus::Reached) {
        m_error = label + ": target cannot be reached by one impulse: " + describe(solved.status);
        return solved;
    }
    applyReported(body, solved.impulse, solved.offset, label, true);
    return solved;
}

void SimRunner::setResetListener(ResetListener listener)
{
    m_resetListener = std::move(listener);
    if (m_resetListener) {
        m_resetListener(*m_runner);
    }
}

} // namespace tumble::viewer
