#include "web_simulation.hpp"

#include "console.hpp"

#include <algorithm>

namespace tumble::web {
namespace {

bool finiteBody(const Body& body)
{
    return isFinite(body.position) && isFinite(body.orientation) &&
           isFinite(body.linearVelocity) && isFinite(body.angularVelocity);
}

} // namespace

std::string WebSimulation::load(const std::string& text, const std::string& sourceName)
{
    // the same parse and the same message as `tumble run FILE` (cli::runReportingErrors)
    try {
        m_scenario = scenario::parseScenario(text, sourceName);
    } catch (const scenario::ScenarioError& error) {
        return "tumble: error: " + std::string(error.what());
    }
    reset();
    return {};
}

void WebSimulation::reset()
{
    if (!m_scenario) {
        return;
    }
    m_runner = std::make_unique<scenario::Runner>(*m_scenario);
    m_totalSteps = scenario::stepCountFor(m_scenario->duration, m_scenario->dt);
    m_summaryPrinted = false;
    m_lastCollisions.clear();
    m_log.str({});
    cli::Console(m_log, false).printHeader(*m_runner, m_totalSteps);
}

bool WebSimulation::finished() const
{
    return !m_runner || m_runner->stepCount() >= m_totalSteps || m_summaryPrinted;
}

int WebSimulation::step()
{
    m_lastCollisions.clear();
    if (finished()) {
        return 0;
    }
    // the last step ends at the duration when that is not a multiple of dt, as in `tumble run`
    scenario::StepReport report;
    try {
        report = m_runner->step(m_scenario->duration);
    } catch (const scenario::ScenarioError& error) {
        m_log << "tumble: error: " << error.what() << '\n';
        m_summaryPrinted = true;
        return 0;
    }
    cli::Console(m_log, false).printStep(*m_runner, report);
    m_lastCollisions = report.collisions;
    for (std::size_t i = 0; i < bodyCount(); ++i) {
        if (!finiteBody(body(i))) {
            m_log << "tumble: error: the state of body " << bodyName(i) << " is not finite at t = "
                  << cli::formatFull(time()) << " s\n";
            m_summaryPrinted = true;
            return 0;
        }
    }
    if (m_runner->stepCount() >= m_totalSteps) {
        finishRun();
    }
    return static_cast<int>(report.collisions.size());
}

long long WebSimulation::runSteps(long long count)
{
    long long taken = 0;
    while (taken < count && !finished()) {
        step();
        ++taken;
    }
    return taken;
}

void WebSimulation::finishRun()
{
    const cli::Console console(m_log, false);
    console.printUnusedImpulses(*m_runner, m_runner->time());
    console.printSummary(*m_runner);
    m_summaryPrinted = true;
}

Real WebSimulation::time() const { return m_runner ? m_runner->time() : 0.0; }
long long WebSimulation::stepCount() const { return m_runner ? m_runner->stepCount() : 0; }
Real WebSimulation::dt() const { return m_scenario ? m_scenario->dt : 0.0; }
Real WebSimulation::duration() const { return m_scenario ? m_scenario->duration : 0.0; }

std::size_t WebSimulation::bodyCount() const { return m_runner ? m_runner->bodies().size() : 0; }

const std::string& WebSimulation::bodyName(std::size_t index) const
{
    return m_runner->bodyName(index);
}

const Body& WebSimulation::body(std::size_t index) const
{
    return m_runner->world().body(m_runner->bodies().at(index));
}

bool WebSimulation::isStatic(std::size_t index) const { return body(index).isStatic(); }

Vec3 WebSimulation::size(std::size_t index) const { return body(index).shape.size; }

BodyState WebSimulation::state(std::size_t index) const
{
    const Body& b = body(index);
    const Vec3& gravity = m_runner->world().settings().gravity;
    return {b.position.x,        b.position.y,        b.position.z,
            b.orientation.w,     b.orientation.x,     b.orientation.y,
            b.orientation.z,     b.linearVelocity.x,  b.linearVelocity.y,
            b.linearVelocity.z,  b.angularVelocity.x, b.angularVelocity.y,
            b.angularVelocity.z, b.kineticEnergy(),   b.potentialEnergy(gravity)};
}

void WebSimulation::setVelocities(std::size_t index, const Vec3& velocity,
                                  const Vec3& angularVelocity)
{
    const BodyId id = m_runner->bodies().at(index);
    m_runner->world().setLinearVelocity(id, velocity);
    m_runner->world().setAngularVelocity(id, angularVelocity);
}

void WebSimulation::applyImpulse(std::size_t index, const Vec3& impulse, const Vec3& offset,
                                 const std::string& label)
{
    applyReported(index, impulse, offset, label, false);
}

ImpulseTarget WebSimulation::applyTarget(std::size_t index, const Vec3& velocity,
                                         const std::optional<Vec3>& angularVelocity,
                                         const std::string& label)
{
    const Body& b = body(index);
    const ImpulseTarget solved =
        solveImpulseTarget(b, velocity, angularVelocity.value_or(b.angularVelocity));
    if (solved.status == ImpulseTargetStatus::Reached) {
        applyReported(index, solved.impulse, solved.offset, label, true);
    }
    return solved;
}

void WebSimulation::applyReported(std::size_t index, const Vec3& impulse, const Vec3& offset,
                                  const std::string& label, bool solvedFromTarget)
{
    // logged as the runner logs a scheduled impulse, so the log pane reads like `tumble run`
    const scenario::AppliedImpulse applied =
        m_runner->applyNow(index, impulse, offset, label, solvedFromTarget);
    cli::Console(m_log, false).printStep(*m_runner, scenario::StepReport{.impulses = {applied}});
}

std::string WebSimulation::takeLog()
{
    std::string text = m_log.str();
    m_log.str({});
    return text;
}

std::vector<ImpulseExperiment> impulseExperiments(const std::string& text,
                                                  const std::string& sourceName,
                                                  const std::string& labelPrefix)
{
    scenario::Scenario loaded;
    try {
        loaded = scenario::parseScenario(text, sourceName);
    } catch (const scenario::ScenarioError&) {
        return {};
    }
    return scenario::impulseExperiments(loaded, labelPrefix);
}

} // namespace tumble::web
