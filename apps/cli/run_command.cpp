#include "run_command.hpp"

#include "cli_options.hpp"
#include "console.hpp"
#include "csv_writer.hpp"
#include "interrupt.hpp"
#include "ledger_csv.hpp"
#include "progress_bar.hpp"

#include "tumble/scenario/runner.hpp"
#include "tumble/scenario/scenario.hpp"
#include "tumble/state_hash.hpp"

#include <algorithm>
#include <array>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <optional>
#include <string_view>

#include <unistd.h>

namespace tumble::cli {
namespace {

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

/// Impact impulses must never add energy (docs/physics/08-energy-ledger.md); say so if they did.
void warnAboutSolverEnergyGain(const scenario::Runner& runner)
{
    for (std::size_t i = 0; i < runner.bodies().size(); ++i) {
        const Body& body = runner.world().body(runner.bodies()[i]);
        const Real scale = 1e-9 * (std::abs(body.ledger.initial) + std::abs(body.ledger.added) + 1.0);
        if (body.ledger.impactWorkLastStep > scale) {
            printWarning("an impact added " + formatFull(body.ledger.impactWorkLastStep) +
                         " J to " + runner.bodyName(i) + " in the step ending at t = " +
                         formatFull(runner.time()) + " s");
        }
    }
}

/// A shorthand option of run and the scenario key it sets.
struct Shorthand {
    std::string_view option;
    std::string_view key;
    const std::string& value;
};

/// Whether one of the --set overrides sets `key` (KEY=VALUE, spaces around KEY allowed).
bool setByOverride(const std::vector<std::string>& overrides, std::string_view key)
{
    return std::any_of(overrides.begin(), overrides.end(), [&](const std::string& text) {
        std::string_view target = std::string_view(text).substr(0, text.find('='));
        const std::size_t first = target.find_first_not_of(" \t");
        const std::size_t last = target.find_last_not_of(" \t");
        target = first == std::string_view::npos ? std::string_view()
                                                  : target.substr(first, last - first + 1);
        return target == key;
    });
}

/// The scenario with --set and the shorthands --duration and --dt applied. The shorthands are
/// overrides given last, so they win; a value they give is checked as a number by CLI11 and passed
/// on in full digits. An error in that value names the shorthand; when --set sets the same key,
/// the two cannot be told apart and the error names --set.
scenario::Scenario loadWithShorthands(const RunOptions& options)
{
    const std::array<Shorthand, 2> shorthands{{{"--duration", "world.duration", options.duration},
                                                {"--dt", "world.dt", options.dt}}};
    std::vector<std::string> overrides = options.overrides;
    for (const Shorthand& shorthand : shorthands) {
        if (!shorthand.value.empty()) {
            overrides.push_back(std::string(shorthand.key) + "=" +
                                formatFull(std::strtod(shorthand.value.c_str(), nullptr)));
        }
    }
    try {
        return scenario::loadScenario(options.file, overrides);
    } catch (const scenario::ScenarioError& error) {
        for (const Shorthand& shorthand : shorthands) {
            if (!shorthand.value.empty() && error.where().file == "--set" &&
                error.key() == shorthand.key && !setByOverride(options.overrides, shorthand.key)) {
                throw UsageError(std::string(shorthand.option), error.problem());
            }
        }
        throw;
    }
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
        ->check(wholeNumberIn(1, std::numeric_limits<int>::max()));
    command->add_option("--energy-csv", options.energyCsvPath,
                        "Write each body's energy ledger, every step, to this CSV file")
        ->type_name("PATH");
    command->add_option("--contacts-csv", options.contactsCsvPath,
                        "Write every contact point of every step to this CSV file")
        ->type_name("PATH");
    command->add_option("--duration", options.duration,
                        "Simulated time, s (same as --set world.duration=T)")
        ->type_name("T")
        ->check(positiveNumber());
    command->add_option("--dt", options.dt, "Time step, s (same as --set world.dt=S)")
        ->type_name("S")
        ->check(positiveNumber());
    command->add_flag("--quiet,-q", options.quiet, "Print no per-event lines");
    addThreadsOption(command, options.threads,
                     "Threads to step the bodies on (default 0: one per core, at most " +
                         std::to_string(kMaxThreads) + "); the results are the same for any "
                         "number");
    command->add_flag("--hash", options.hash,
                      "Print a hash of the final state (FNV-1a 64 of every body's position, "
                      "orientation and velocities) to compare runs");
    command->add_option("--set", options.overrides,
                        "Override a scenario value, KEY=VALUE (world.dt=0.001, rb.elasticity=0.7); "
                        "repeatable")
        ->type_name("KEY=VALUE")
        ->allow_extra_args(false);
    return command;
}

int runCommand(const RunOptions& options)
{
    // an output must not replace the scenario or another output (issue 14, item 11)
    checkDistinctPaths(options.file, {{"--csv", options.csvPath},
                                      {"--energy-csv", options.energyCsvPath},
                                      {"--contacts-csv", options.contactsCsvPath}});
    scenario::Scenario loaded = loadWithShorthands(options);
    loaded.settings.recordContacts = !options.contactsCsvPath.empty();
    loaded.settings.threads = options.threads;
    scenario::Runner runner(loaded);

    // with the CSV on stdout the console report moves to stderr and drops the event lines
    const bool csvToStdout = options.csvPath == "-";
    const Console console(csvToStdout ? std::cerr : std::cout, options.quiet || csvToStdout);
    std::optional<CsvWriter> csv;
    if (!options.csvPath.empty()) {
        csv.emplace(options.csvPath);
    }
    std::optional<EnergyCsv> energyCsv;
    if (!options.energyCsvPath.empty()) {
        energyCsv.emplace(options.energyCsvPath);
        energyCsv->writeStep(runner);
    }
    std::optional<ContactsCsv> contactsCsv;
    if (!options.contactsCsvPath.empty()) {
        contactsCsv.emplace(options.contactsCsvPath);
    }

    const long long stepCount = scenario::stepCountFor(loaded.duration, loaded.dt);
    console.printHeader(runner, stepCount);
    if (csv) {
        csv->writeSample(runner);
    }
    // SIGINT/SIGTERM stop the loop at the next step; the output is then completed up to there
    const InterruptGuard interruptGuard;
    // a bar on stderr when it is a terminal and no event lines go there (issue 14, item 15)
    const bool progress = isatty(STDERR_FILENO) != 0 && (options.quiet || options.csvPath == "-");
    ProgressBar bar(stepCount, stepCount, "steps");
    long long lastSample = 0;
    for (long long i = 0; i < stepCount && InterruptGuard::received() == 0; ++i) {
        if (progress) {
            bar.update(i);
        }
        // the last step ends at the duration when that is not a multiple of dt (issue 14, item 12)
        const scenario::StepReport report = runner.step(loaded.duration);
        console.printStep(runner, report);
        if (const auto bad = firstNonFiniteBody(runner)) {
            printError("the state of body " + runner.bodyName(*bad) +
                       " is not finite at t = " + formatFull(runner.time()) + " s");
            return kExitNonFinite;
        }
        if (csv && runner.stepCount() % options.every == 0) {
            csv->writeSample(runner);
            lastSample = runner.stepCount();
        }
        if (energyCsv) {
            energyCsv->writeStep(runner);
        }
        if (contactsCsv) {
            contactsCsv->writeStep(runner);
        }
        warnAboutSolverEnergyGain(runner);
    }
    if (progress) {
        ProgressBar::clear();
    }
    const int stoppedBy = InterruptGuard::received();
    if (stoppedBy != 0) {
        printError(std::string("interrupted by ") + signalName(stoppedBy) + ": stopped at t = " +
                   formatFull(runner.time()) + " s after " + std::to_string(runner.stepCount()) +
                   " of " + std::to_string(stepCount) + " steps; output files hold the run up " +
                   "to that time");
    } else {
        console.printUnusedImpulses(runner, runner.time());
    }
    // the CSV always ends with the final state, whatever --every
    if (csv && lastSample != runner.stepCount()) {
        csv->writeSample(runner);
    }
    console.printSummary(runner);
    if (options.hash) {
        char hash[32];
        std::snprintf(hash, sizeof hash, "%016" PRIx64, stateHash(runner.world(), runner.bodies()));
        (csvToStdout ? std::cerr : std::cout) << "state hash: " << hash << '\n';
    }
    if (csv) {
        csv->finish();
    }
    if (energyCsv) {
        energyCsv->finish();
    }
    if (contactsCsv) {
        contactsCsv->finish();
    }
    return stoppedBy != 0 ? kExitSignalBase + stoppedBy : kExitOk;
}

} // namespace tumble::cli
