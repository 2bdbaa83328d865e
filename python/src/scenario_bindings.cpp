// tumble.load_scenario and tumble.Scenario: scenario files as the CLI reads them, their errors as
// tumble.ScenarioError with the CLI's message, and runs that give `tumble run --csv`'s numbers.
#include "bindings.hpp"
#include "convert.hpp"
#include "run_loop.hpp"

#include "tumble/scenario/runner.hpp"
#include "tumble/scenario/scenario.hpp"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <optional>
#include <vector>

namespace tumble::python {
namespace {

using scenario::Scenario;

/// `tumble run` on the scenario: the same Runner (scheduled impulses included), the same samples.
py::array runScenario(const Scenario& loaded, long long every, std::optional<double> duration,
                      int threads, const py::object& progress)
{
    if (every < 1) {
        throw py::value_error("every must be >= 1");
    }
    if (threads < 0) {
        throw py::value_error("threads must be >= 0 (0: one per core)");
    }
    Scenario copy = loaded;
    if (duration) {
        requirePositive(*duration, "duration", true);
        copy.duration = *duration;
    }
    copy.settings.threads = threads;
    scenario::Runner runner(copy);
    const long long stepCount = scenario::stepCountFor(copy.duration, copy.dt);
    const auto step = [&](long long) { (void)runner.step(copy.duration); };
    const auto sample = [&](Trajectory& trajectory) {
        trajectory.sample(runner.world(), runner.bodies(), runner.time());
    };
    return runSampled(stepCount, every, runner.bodies().size(), progress, step, sample);
}

/// A tumble.World holding the scenario's ground, planes and bodies (named as in the file).
std::shared_ptr<WorldState> worldOf(const Scenario& loaded)
{
    scenario::BuiltWorld built = scenario::buildWorld(loaded);
    auto state = std::make_shared<WorldState>(WorldState{std::move(built.world), {}, {}, false});
    for (std::size_t i = 0; i < built.bodies.size(); ++i) {
        state->adopt(built.bodies[i], loaded.bodies[i].name);
    }
    return state;
}

std::vector<std::string> bodyNames(const Scenario& loaded)
{
    std::vector<std::string> names;
    for (const scenario::BodySpec& body : loaded.bodies) {
        names.push_back(body.name);
    }
    return names;
}

} // namespace

void bindScenario(py::module_& module)
{
    py::class_<Scenario> scenarioClass(module, "Scenario", R"doc(
A scenario file as `tumble run` reads it (tumble.load_scenario). Scenario.run gives the numbers
of `tumble run --csv`; Scenario.world() gives a tumble.World to go on from by hand.
)doc");
    scenarioClass.def_readonly("source", &Scenario::sourceName, "The file it was read from.")
        .def_readonly("dt", &Scenario::dt, "Fixed time step, s.")
        .def_readonly("duration", &Scenario::duration, "How long `tumble run` simulates, s.")
        .def_property_readonly(
            "gravity", [](const Scenario& s) { return toArray(s.settings.gravity); },
            "Gravitational acceleration, m/s^2.")
        .def_property_readonly("bodies", &bodyNames,
                               "Body names in file order: the `body` column of Scenario.run.")
        .def_property_readonly(
            "has_throw", [](const Scenario& s) { return s.throwSpec.has_value(); },
            "Whether the file has a [throw] table (for tumble.throw).");
    scenarioClass.def("run", &runScenario, py::kw_only(), py::arg("every") = 1,
                      py::arg("duration") = py::none(), py::arg("threads") = 0,
                      py::arg("progress") = false, R"doc(
Runs the scenario as `tumble run` does (scheduled impulses included) and returns the samples as
World.run does; `body` is the index in Scenario.bodies. duration: default the file's. Releases
the GIL; Ctrl-C raises KeyboardInterrupt with the samples so far as its `partial` attribute.
)doc");
    scenarioClass.def("world", &worldOf, R"doc(
A new tumble.World with the scenario's settings, ground, planes and bodies (named as in the file;
scheduled impulses are not applied).
)doc");
    scenarioClass.def("__repr__", [](const Scenario& s) {
        return "<tumble.Scenario " + s.sourceName + ">";
    });

    module.def(
        "load_scenario",
        [](const std::filesystem::path& path, const std::vector<std::string>& overrides) {
            Scenario loaded = scenario::loadScenario(path, overrides);
            // the engine asserts on bad bodies: report them now, as `tumble check` does
            (void)scenario::buildWorld(loaded);
            return loaded;
        },
        py::arg("path"), py::arg("overrides") = std::vector<std::string>{}, R"doc(
Reads and checks a scenario file. overrides: "KEY=VALUE" strings as `tumble run --set` takes
them ("world.dt=0.001", "rb.elasticity=0.7"). A bad file raises tumble.ScenarioError (a
ValueError) whose message is the CLI's: "FILE:LINE: KEY: problem".
)doc");
}

} // namespace tumble::python
