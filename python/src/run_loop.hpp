// runSampled: the loop of World.run and Scenario.run. It steps without the GIL (other Python
// threads keep running), samples like `tumble run --csv` (before the first step, every `every`
// steps, and after the last) and stops on Ctrl-C with the samples so far on the exception.
#pragma once

#include "long_call.hpp"
#include "trajectory.hpp"
#include "world_state.hpp"

#include <pybind11/pybind11.h>

namespace tumble::python {

namespace py = pybind11;

/// Marks a world as running for the scope (around runSampled, which releases the GIL); made and
/// destroyed with the GIL held.
class RunningScope {
public:
    explicit RunningScope(WorldState& state) : m_state(state)
    {
        (void)m_state.checked();
        m_state.running = true;
    }
    ~RunningScope() { m_state.running = false; }
    RunningScope(const RunningScope&) = delete;
    RunningScope& operator=(const RunningScope&) = delete;

private:
    WorldState& m_state;
};

/// Runs `stepCount` steps: `step()` advances one, `sample(trajectory)` appends the state now.
/// `rowsPerSample` sizes the buffer up front so sampling does not reallocate in the loop.
template <typename Step, typename Sample>
py::array runSampled(long long stepCount, long long every, std::size_t rowsPerSample,
                     const py::object& progress, Step step, Sample sample)
{
    LongCall call(progress, stepCount, "steps");
    Trajectory trajectory;
    trajectory.reserve(static_cast<std::size_t>(sampleCount(stepCount, every)) * rowsPerSample);
    long long done = 0;
    {
        const py::gil_scoped_release release;
        sample(trajectory);
        long long lastSample = 0;
        while (done < stepCount && !call.poll(done)) {
            step(done);
            ++done;
            if (done % every == 0) {
                sample(trajectory);
                lastSample = done;
            }
        }
        // the samples always end with the final state, whatever `every`
        if (lastSample != done) {
            sample(trajectory);
        }
    }
    py::array result = trajectory.release();
    call.finish(done, result);
    return result;
}

} // namespace tumble::python
