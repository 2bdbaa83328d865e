// LongCall: what a call that runs without the GIL (World.run, Scenario.run, throw, validate)
// does between units of work: a few times a second it takes the GIL back so that Python can run
// its signal handlers (Ctrl-C raises KeyboardInterrupt) and a progress bar can be drawn.
#pragma once

#include <pybind11/pybind11.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

namespace tumble::python {

namespace py = pybind11;

class LongCall {
public:
    /// Made with the GIL held, before the loop. `progress` is False/None (nothing), True (a bar on
    /// sys.stderr, tumble._progress.ProgressBar) or a callable progress(done, total).
    LongCall(const py::object& progress, std::int64_t total, const std::string& unit);

    /// Called without the GIL, on the thread that released it, after each unit of work. At most
    /// every kPollSeconds it takes the GIL, runs the signal handlers and reports `done`. Returns
    /// true once the call must stop (a handler or the progress callable raised); never throws,
    /// so it is safe inside an OpenMP loop.
    bool poll(std::int64_t done);

    /// With the GIL held, after the loop: reports `done` a last time and closes the bar; when
    /// the loop was stopped, re-raises the exception with `partial` as its `partial` attribute
    /// (what was computed before the stop).
    void finish(std::int64_t done, const py::object& partial = py::none());

    [[nodiscard]] bool stopped() const { return m_error.has_value(); }

private:
    using Clock = std::chrono::steady_clock;
    /// Seconds between polls: Ctrl-C answers within this, and the cost stays far below a step.
    static constexpr double kPollSeconds = 0.1;

    void report(std::int64_t done);

    py::object m_progress;
    bool m_ownBar = false;
    std::int64_t m_total;
    Clock::time_point m_nextPoll;
    std::optional<py::error_already_set> m_error;
};

} // namespace tumble::python
