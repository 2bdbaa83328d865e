// The engine of tumble.throw (python/tumble/_throw.py): the throws of `tumble throw` run by the
// scenario library's runThrowBatch, without the GIL, and the dice statistics of its report.
#include "bindings.hpp"
#include "long_call.hpp"

#include "tumble/scenario/dice_statistics.hpp"
#include "tumble/scenario/throw_batch.hpp"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <vector>

namespace tumble::python {
namespace {

using scenario::Scenario;
using scenario::ThrowOutcome;

/// (face, rest_time, finished) arrays of the throws: face in CuboidFace order (+x, -x, +y, -y,
/// +z, -z) or -1 when unsettled, rest time NaN when unsettled.
py::tuple outcomeArrays(const std::vector<ThrowOutcome>& outcomes,
                        const std::vector<std::uint8_t>& finished)
{
    const auto count = static_cast<py::ssize_t>(outcomes.size());
    py::array_t<std::int8_t> faces(count);
    py::array_t<double> restTimes(count);
    py::array_t<bool> done(count);
    auto face = faces.mutable_unchecked<1>();
    auto restTime = restTimes.mutable_unchecked<1>();
    auto ran = done.mutable_unchecked<1>();
    for (py::ssize_t i = 0; i < count; ++i) {
        const ThrowOutcome& outcome = outcomes[static_cast<std::size_t>(i)];
        face(i) = outcome.settled ? static_cast<std::int8_t>(outcome.faceDown) : -1;
        restTime(i) = outcome.settled ? outcome.restTime : std::numeric_limits<double>::quiet_NaN();
        ran(i) = finished[static_cast<std::size_t>(i)] != 0;
    }
    return py::make_tuple(faces, restTimes, done);
}

py::tuple runThrows(const Scenario& loaded, std::int64_t throws, std::uint64_t seed, int threads,
                    const py::object& progress)
{
    if (!loaded.throwSpec) {
        throw scenario::ScenarioError(scenario::SourceLocation{loaded.sourceName, 0}, "throw",
                                      "missing: tumble throw needs a [throw] table "
                                      "(docs/scenario-format.md)");
    }
    // the module runs the single-die model; several dice (or a region) are `tumble throw`'s
    if (loaded.bodies.size() != 1 || !loaded.ground || loaded.throwSpec->region ||
        loaded.throwSpec->release != scenario::ThrowRelease::Each) {
        throw scenario::ScenarioError(scenario::SourceLocation{loaded.sourceName, 0}, "throw",
                                      "the Python module throws one die over a [ground]; use "
                                      "`tumble throw` for several dice or a region");
    }
    if (throws < 1) {
        throw py::value_error("throws must be >= 1");
    }
    if (threads < 0) {
        throw py::value_error("threads must be >= 0 (0: one per core)");
    }
    const int used = scenario::parallelThrowBuild()
                         ? (threads > 0 ? threads : std::max(1, scenario::throwCoreCount()))
                         : 1;
    std::vector<ThrowOutcome> outcomes(static_cast<std::size_t>(throws));
    std::vector<std::uint8_t> finished(outcomes.size(), 0);
    LongCall call(progress, throws, "throws");
    // the caller's thread polls; every thread reads the flag it sets
    std::atomic<bool> stop{false};
    scenario::ThrowBatchHooks hooks;
    hooks.stopRequested = [&stop] { return stop.load(std::memory_order_relaxed); };
    hooks.progress = [&](std::int64_t done) {
        if (call.poll(done)) {
            stop.store(true, std::memory_order_relaxed);
        }
    };
    std::int64_t done = 0;
    {
        const py::gil_scoped_release release;
        done = scenario::runThrowBatch(loaded, seed, 0, outcomes, finished, used, hooks);
    }
    py::tuple arrays = outcomeArrays(outcomes, finished);
    call.finish(done, arrays);
    return py::make_tuple(arrays[0], arrays[1], used);
}

} // namespace

void bindThrow(py::module_& module)
{
    module.def("_throw_outcomes", &runThrows, py::arg("scenario"), py::arg("throws"),
               py::arg("seed"), py::arg("threads"), py::arg("progress"),
               "(faces, rest_times, threads) of `tumble throw`'s throws; see tumble.throw.");
    module.def(
        "_wilson_interval",
        [](std::int64_t successes, std::int64_t trials, double confidence) {
            if (!(confidence > 0.0 && confidence < 1.0)) {
                throw py::value_error("confidence must be in (0, 1)");
            }
            const scenario::ProbabilityInterval interval =
                scenario::wilsonInterval(successes, trials, confidence);
            return py::make_tuple(interval.low, interval.high);
        },
        "Wilson's score interval (docs/dice.md, (D.1)).");
    module.def(
        "_chi_square_uniform",
        [](const std::vector<std::int64_t>& counts) {
            const double statistic = scenario::chiSquareUniformStatistic(counts);
            const int degrees = static_cast<int>(counts.size()) - 1;
            return py::make_tuple(statistic,
                                  degrees >= 1 ? scenario::chiSquarePValue(statistic, degrees)
                                               : std::numeric_limits<double>::quiet_NaN());
        },
        "Pearson's statistic against equal counts and its p-value (docs/dice.md, (D.2)).");
}

} // namespace tumble::python
