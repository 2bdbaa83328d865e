// WebSimulation: one scenario run for the page, as `tumble run` steps it, with the run's console
// lines collected for the log pane. Plain C++; bindings.cpp shows it to JavaScript.
#pragma once

#include "tumble/impulse_target.hpp"
#include "tumble/math.hpp"
#include "tumble/scenario/impulse_experiments.hpp"
#include "tumble/scenario/runner.hpp"
#include "tumble/scenario/scenario.hpp"

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace tumble::web {

/// One body's state in the columns of `tumble run --csv` after time and name: position,
/// orientation (w, x, y, z), velocity, angular velocity, kinetic and potential energy.
using BodyState = std::array<Real, 15>;

class WebSimulation {
public:
    /// Parses `text` as the scenario file `sourceName` and starts its run. Returns "" when it
    /// loads, else the line `tumble run` prints for it ("tumble: error: FILE:LINE: KEY: problem");
    /// a scenario that does not load leaves the previous one running.
    std::string load(const std::string& text, const std::string& sourceName);
    /// Starts the loaded scenario again from t = 0 (the log starts again with its header).
    void reset();

    [[nodiscard]] bool loaded() const { return m_runner != nullptr; }
    /// True once the run has taken the scenario's steps (its duration, as `tumble run`).
    [[nodiscard]] bool finished() const;
    /// Takes one fixed step, the same as `tumble run` does; does nothing once finished. Returns
    /// the number of impacts in the step.
    int step();
    /// Takes up to `count` steps, stopping at the end of the run; returns the steps taken.
    long long runSteps(long long count);

    [[nodiscard]] Real time() const;
    [[nodiscard]] long long stepCount() const;
    /// The run's number of steps, ceil(duration / dt) as `tumble run`.
    [[nodiscard]] long long totalSteps() const { return m_totalSteps; }
    [[nodiscard]] Real dt() const;
    [[nodiscard]] Real duration() const;

    [[nodiscard]] std::size_t bodyCount() const;
    [[nodiscard]] const std::string& bodyName(std::size_t index) const;
    [[nodiscard]] bool isStatic(std::size_t index) const;
    [[nodiscard]] Vec3 size(std::size_t index) const;
    [[nodiscard]] BodyState state(std::size_t index) const;
    [[nodiscard]] const Body& body(std::size_t index) const;
    [[nodiscard]] const scenario::Runner& runner() const { return *m_runner; }

    /// Sets a body's velocities (the impulse tool's "start from the experiment's velocities").
    void setVelocities(std::size_t index, const Vec3& velocity, const Vec3& angularVelocity);
    /// Applies an impulse at an offset from the centre of mass now, logged as `label`.
    void applyImpulse(std::size_t index, const Vec3& impulse, const Vec3& offset,
                      const std::string& label);
    /// Solves for and applies the impulse that reaches a target velocity (and spin, when given).
    ImpulseTarget applyTarget(std::size_t index, const Vec3& velocity,
                              const std::optional<Vec3>& angularVelocity, const std::string& label);

    /// The impacts of the last step, in order (for the impulse arrows and the plots' marks).
    [[nodiscard]] const std::vector<CollisionEvent>& lastCollisions() const
    {
        return m_lastCollisions;
    }

    /// The console lines written since the last call.
    std::string takeLog();

private:
    void applyReported(std::size_t index, const Vec3& impulse, const Vec3& offset,
                       const std::string& label, bool solvedFromTarget);
    void finishRun();

    std::optional<scenario::Scenario> m_scenario;
    std::unique_ptr<scenario::Runner> m_runner;
    long long m_totalSteps = 0;
    bool m_summaryPrinted = false;
    std::vector<CollisionEvent> m_lastCollisions;
    std::ostringstream m_log;
};

using scenario::ImpulseExperiment;

/// The impulse experiments of a handout file's text, labelled "<labelPrefix>" when the file has
/// one and "<labelPrefix>: <body>" when it has several; none when the text does not load.
std::vector<ImpulseExperiment> impulseExperiments(const std::string& text,
                                                  const std::string& sourceName,
                                                  const std::string& labelPrefix);

} // namespace tumble::web
