// SimRunner: the viewer's simulation side. Owns the scenario's Runner, turns frame time into
// fixed steps (play, pause, single step, time scale), resets, reloads and switches scenarios,
// and applies the panels' edits through World's setters. It does no physics of its own.
#pragma once

#include "viewer/fixed_step.hpp"

#include "tumble/contact.hpp"
#include "tumble/impulse_target.hpp"
#include "tumble/material.hpp"
#include "tumble/math.hpp"
#include "tumble/scenario/runner.hpp"
#include "tumble/scenario/scenario.hpp"
#include "tumble/world.hpp"

#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tumble::viewer {

class SimRunner {
public:
    /// Called after every fixed step, and after an impulse applied from the viewer.
    using StepListener =
        std::function<void(const scenario::Runner&, const scenario::StepReport&)>;
    /// Called whenever a new Runner starts: a scenario opened, reloaded or reset.
    using ResetListener = std::function<void(const scenario::Runner&)>;

    /// Time scale limits (slow motion 0.1x to 2x).
    static constexpr double kMinTimeScale = 0.1;
    static constexpr double kMaxTimeScale = 2.0;
    /// At most this much simulated time is stepped per frame, s; beyond it the viewer falls
    /// behind real time rather than taking ever longer frames.
    static constexpr double kMaxSecondsPerFrame = 0.1;

    /// Loads `file` with "KEY=VALUE" overrides (kept for reload). Throws ScenarioError.
    explicit SimRunner(std::filesystem::path file, std::vector<std::string> overrides = {});
    ~SimRunner();
    SimRunner(const SimRunner&) = delete;
    SimRunner& operator=(const SimRunner&) = delete;

    // scenario

    [[nodiscard]] const std::filesystem::path& file() const { return m_file; }
    /// Increases each time another scenario file is opened.
    [[nodiscard]] int scenarioSerial() const { return m_scenarioSerial; }
    /// Opens another file (without the overrides). On a bad file keeps the current scenario,
    /// sets error() and returns false.
    bool open(const std::filesystem::path& file);
    /// Reads the current file from disk again (edits in the panels are dropped).
    bool reload();
    /// Starts the current scenario, with the panels' edits, from t = 0.
    void reset();

    /// The scenario as edited in the panels; reset() starts from it.
    [[nodiscard]] const scenario::Scenario& scenario() const { return m_scenario; }
    [[nodiscard]] const scenario::Runner& runner() const { return *m_runner; }
    [[nodiscard]] const World& world() const { return m_runner->world(); }
    [[nodiscard]] std::size_t bodyCount() const { return m_runner->bodies().size(); }
    [[nodiscard]] const Body& body(std::size_t index) const;
    /// The last impact of each body (by scenario index), if it has had one.
    [[nodiscard]] const std::vector<std::optional<CollisionEvent>>& lastCollisions() const
    {
        return m_lastCollisions;
    }
    /// The last problem: a file that did not load, an unreachable target, a non-finite state.
    [[nodiscard]] const std::string& error() const { return m_error; }
    void clearError() { m_error.clear(); }

    // time

    [[nodiscard]] Real time() const { return m_runner->time(); }
    [[nodiscard]] bool paused() const { return m_paused; }
    void setPaused(bool paused);
    void togglePaused() { setPaused(!m_paused); }
    /// Takes one fixed step and pauses.
    void stepOnce();
    [[nodiscard]] double timeScale() const { return m_timeScale; }
    /// Clamped to [kMinTimeScale, kMaxTimeScale].
    void setTimeScale(double scale);
    /// Takes the fixed steps that `frameSeconds` of real time x timeScale make due (none while
    /// paused); returns how many.
    int advance(double frameSeconds);
    /// True when the last advance could not keep up with real time.
    [[nodiscard]] bool fellBehind() const { return m_accumulator.fellBehind(); }
    /// Steps (paused or not) until time() has reached `time` as `tumble run` would: after
    /// ceil(time / dt) steps from the start.
    void advanceTo(Real time);

    // edits: applied to the running World now, and kept in scenario() for reset

    void setGravity(const Vec3& gravity);
    void setIntegrator(Integrator integrator);
    void setResponse(ContactResponse response);
    /// Takes effect at the next reset (the Runner's steps are counted in the old dt).
    void setDt(Real dt);
    void setMass(std::size_t body, Real mass);
    void setSize(std::size_t body, const Vec3& size);
    void setMaterial(std::size_t body, const Material& material);

    // pokes: applied to the running World only

    void setVelocities(std::size_t body, const Vec3& velocity, const Vec3& angularVelocity);
    /// Applies `impulse` (N s) at `offset` from the centre of mass (world axes, m) now.
    void applyImpulse(std::size_t body, const Vec3& impulse, const Vec3& offset,
                      const std::string& label);
    /// Solves for the impulse that gives the body these velocities (the angular velocity
    /// unchanged when none is given) and applies it when it exists; sets error() when not.
    ImpulseTarget applyTarget(std::size_t body, const Vec3& targetVelocity,
                              const std::optional<Vec3>& targetAngularVelocity,
                              const std::string& label);

    void setStepListener(StepListener listener) { m_stepListener = std::move(listener); }
    /// Also calls `listener` at once for the current Runner.
    void setResetListener(ResetListener listener);

private:
    void start(scenario::Scenario scenario);
    bool stepChecked();
    void applyReported(std::size_t body, const Vec3& impulse, const Vec3& offset,
                       const std::string& label, bool solvedFromTarget);
    void record(const scenario::StepReport& report);
    [[nodiscard]] BodyId idOf(std::size_t body) const;
    World& mutableWorld();

    std::filesystem::path m_file;
    std::vector<std::string> m_overrides;
    int m_scenarioSerial = 0;
    scenario::Scenario m_scenario;
    std::unique_ptr<scenario::Runner> m_runner;
    std::vector<std::optional<CollisionEvent>> m_lastCollisions;
    FixedStepAccumulator m_accumulator;
    bool m_paused = false;
    double m_timeScale = 1.0;
    std::string m_error;
    StepListener m_stepListener;
    ResetListener m_resetListener;
};

} // namespace tumble::viewer
