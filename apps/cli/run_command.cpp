#include "run_command.hpp"

#include "console.hpp"
#include "csv_writer.hpp"

#include "tumble/scenario/runner.hpp"
#include "tumble/scenario/scenario.hpp"

#include <cmath>
#include <iostream>
#include <limits>
#include <optional>

namespace tumble::cli {
namespace {

/// Slack when counting steps, so a duration that is a whole number of steps up to rounding
/// (10 / (1/240) = 2400.0000000004) does not get one step more.
constexpr Real kStepCountSlack = 1e-6;

/// Number of fixed steps after which time() >= duration.
long long stepsFor(Real duration, Real dt)
{
    return static_cast<long long>(std::ceil(duration / dt - kStepCountSlack));
}

/// Index of the first body whose state is not finite, if any.
std::optional<std::size_t> firstNonFiniteBody(const scenario::Runner& runner)
{
    for (std::size_t i = 0; i < runner.bodies().size(); ++i) {
        const Body& body = runner.world().body(runner.bodies()[i]);
        if (!isFinite(body.position) || !isFinite(body.orientation) ||
            !isFinite(body.linearVelocity) || !isFinite(body.angularVelocity)) {
            return i;
        }
    }
    return std::nullopt;
}

} // namespace

CLI::App* addRunCommand(CLI::App& app, RunOptions& options)
{
    CLI::App* command = app.add_subcommand("run", "Simulate a scenario and report what happens");
    command->add_option("FILE", options.file, "Scenario file (TOML)")->required()->type_name("");
    command->add_option("--csv", options.csvPath,
                        "Write the state of every body to this CSV file ('-' for stdout)")
        ->type_name("PATH");
    command->add_option("--every", options.every, "Steps between CSV samples (>= 1, default 1)")
        ->type_name("N")
        ->check(CLI::Range(1, std::numeric_limits<int>::max()).description(""));
    command->add_option("--duration", options.duration,
                        "Simulated time, s (same as --set world.duration=T)")
        ->type_name("T");
    command->add_option("--dt", options.dt, "Time step, s (same as --set world.dt=S)")
        ->type_name("S");
    command->add_flag("--quiet,-q", options.quiet, "Print no per-event lines");
    command->add_option("--set", options.overrides,
                        "Override a scenario value, KEY=VALUE (world.dt=0.001, rb.elasticity=0.7); "
                        "repeatable")
        ->type_name("KEY=VALUE")
        ->allow_extra_args(false);
    return command;
}

int runCommand(const RunOptions& options)
{
    // the shorthands are overrides too, given last so they win
    std::vector<std::string> overrides = options.overrides;
    if (!options.duration.empty()) {
        overrides.push_back("world.duration=" + options.duration);
    }
    if (!options.dt.empty()) {
        overrides.push_back("world.dt=" + options.dt);
    }
    const scenario::Scenario loaded = scenario::loadScenario(options.file, overrides);
    scenario::Runner runner(loaded);

    // with the CSV on stdout the console report moves to stderr and drops the event lines
    const bool csvToStdout = options.csvPath == "-";
    const Console console(csvToStdout ? std::cerr : std::cout, options.quiet || csvToStdout);
    std::optional<CsvWriter> csv;
    if (!options.csvPath.empty()) {
        csv.emplace(options.csvPath);
    }

    const long long stepCount = stepsFor(loaded.duration, loaded.dt);
    console.printHeader(runner, stepCount);
    if (csv) {
        csv->writeSample(runner);
    }
    for (long long i = 0; i < stepCount; ++i) {
        const scenario::StepReport report = runner.step();
        console.printStep(runner, report);
        if (const auto bad = firstNonFiniteBody(runner)) {
            printError("the state of body " + runner.bodyName(*bad) +
                       " is not finite at t = " + formatFull(runner.time()) + " s");
            return kExitNonFinite;
        }
        if (csv && runner.stepCount() % options.every == 0) {
            csv->writeSample(runner);
        }
    }
    console.printUnusedImpulses(runner, runner.time());
    console.printSummary(runner);
    if (csv) {
        csv->finish();
    }
    return kExitOk;
}

} // namespace tumble::cli
