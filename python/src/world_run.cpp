// World.step, World.run and World.collisions: stepping a tumble.World from Python.
#include "bindings.hpp"
#include "collision.hpp"
#include "convert.hpp"
#include "run_loop.hpp"

#include "tumble/scenario/runner.hpp"

#include <pybind11/stl.h>


namespace tumble::python {
namespace {

/// Steps as tumble run's Runner does, so that a scene built here gives the CLI's numbers to the
/// bit: step k ends at (k + 1) dt (its length fixedStepLength(k, dt)), and a duration that is
/// not a multiple of dt ends on a shortened step.
py::array run(WorldState& state, double duration, double dt, long long every,
              const py::object& progress)
{
    requirePositive(duration, "duration", true);
    requirePositive(dt, "dt");
    if (every < 1) {
        throw py::value_error("every must be >= 1");
    }
    World& world = state.checked();
    const long long stepCount = scenario::stepCountFor(duration, dt);
    const double start = world.time();
    // the Runner's tolerance for a step end that is the duration up to rounding
    const double tolerance = 1e-9 * dt;
    // sample times are those of the step ends, counted from the start as the CLI's are (not
    // the summed step lengths)
    double ended = 0.0;
    const auto step = [&](long long k) {
        const double begin = static_cast<double>(k) * dt;
        double end = static_cast<double>(k + 1) * dt;
        if (duration < end - tolerance && duration > begin) {
            end = duration;
        }
        world.step(end - begin);
        ended = end;
    };
    const auto sample = [&](Trajectory& trajectory) {
        trajectory.sample(world, state.ids, start + ended);
    };
    const RunningScope running(state);
    return runSampled(stepCount, every, state.ids.size(), progress, step, sample);
}

} // namespace

void bindWorldRun(WorldClass& world)
{
    world.def(
        "step",
        [](WorldState& s, double dt) {
            requirePositive(dt, "dt");
            s.checked().step(dt);
        },
        py::arg("dt"), "Advances every awake body by dt seconds.");
    world.def("run", &run, py::kw_only(), py::arg("duration"), py::arg("dt") = 1.0 / 240.0,
              py::arg("every") = 1, py::arg("progress") = false, R"doc(
Steps the world for `duration` seconds in fixed steps of `dt` and returns the samples as a NumPy
structured array with the columns of `tumble run --csv`: time, body (Body.index), x, y, z,
qw, qx, qy, qz, vx, vy, vz, wx, wy, wz, kinetic, potential. One row per dynamic body per sample:
before the first step, every `every` steps and after the last. Times count from World.time at
the call.

The steps run without the GIL (other Python threads go on) and stop on Ctrl-C: the
KeyboardInterrupt carries the samples so far as its `partial` attribute, and the world stays
where it stopped. progress: True draws a bar on stderr; a callable is called as
progress(done, total) a few times a second.
)doc");
    world.def_property_readonly(
        "collisions",
        [](const std::shared_ptr<WorldState>& s) {
            py::list collisions;
            for (const CollisionEvent& event : s->checked().collisions()) {
                collisions.append(makeCollision(s, event));
            }
            return collisions;
        },
        "The impacts of the last step, in order (a list of tumble.Collision).");
}

} // namespace tumble::python
