#include "throw_command.hpp"

#include "cli_options.hpp"
#include "console.hpp"
#include "interrupt.hpp"
#include "mpi_session.hpp"
#include "output_file.hpp"
#include "throw_batch.hpp"
#include "throw_dice_command.hpp"
#include "throw_report.hpp"

#include "tumble/scenario/scenario.hpp"
#include "tumble/scenario/throw.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <limits>
#include <vector>

namespace tumble::cli {
namespace {

/// The scenario, which must have a [throw] table.
scenario::Scenario loadThrowScenario(const ThrowOptions& options)
{
    scenario::Scenario loaded = scenario::loadScenario(options.file, options.overrides);
    if (!loaded.throwSpec) {
        throw scenario::ScenarioError(scenario::SourceLocation{options.file, 0}, "throw",
                                      "missing: tumble throw needs a [throw] table "
                                      "(docs/scenario-format.md)");
    }
    // the engine asserts on bad bodies; report them as bad input instead
    (void)scenario::buildWorld(loaded);
    if (!singleDieThrow(loaded)) {
        checkDicePlacement(options, loaded);
    }
    return loaded;
}

/// --replay I --out PATH: throw I as an ordinary scenario file, and what it gives.
int writeReplay(const ThrowOptions& options, const scenario::Scenario& loaded)
{
    const auto index = static_cast<std::uint64_t>(options.replay);
    const scenario::ThrowState state = scenario::drawThrow(loaded, options.seed, index);
    const std::string comment =
        "Throw " + std::to_string(index) + " of " + options.file + " with seed " +
        std::to_string(options.seed) + ", written by `tumble throw " + options.file + " --seed " +
        std::to_string(options.seed) + " --replay " + std::to_string(index) +
        "`.\n`tumble run` on this file reproduces the throw: the same face down at the same "
        "rest time.";
    OutputFile output(options.outPath);
    const std::string text = scenario::throwScenarioToml(loaded, state, comment);
    std::fwrite(text.data(), 1, text.size(), output.handle());
    output.finish();

    const scenario::ThrowOutcome outcome = scenario::runThrow(loaded, state);
    std::cout << "throw " << index << " written to " << options.outPath << ": ";
    if (outcome.settled) {
        std::cout << "came to rest at t = " << formatFull(outcome.restTime) << " s on face "
                  << faceName(outcome.faceDown) << '\n';
    } else {
        std::cout << "not at rest by max_time = " << formatFull(loaded.throwSpec->maxTime)
                  << " s\n";
    }
    return kExitOk;
}

void printHeader(const ThrowOptions& options, const scenario::Scenario& loaded, int threads,
                 int ranks)
{
    const BodyDef& die = loaded.bodies.front().def;
    std::cout << "scenario: " << options.file << '\n'
              << "die (body " << loaded.bodies.front().name
              << "): size = " << formatVec3(die.shape.size)
              << " m, mass = " << formatFixed(die.mass)
              << " kg, elasticity = " << formatFixed(die.material.restitution)
              << ", friction = " << formatFixed(die.material.friction) << '\n'
              << "throws = " << options.throws << ", seed = " << options.seed
              << ", threads = " << threads
              << (parallelBuild() ? "" : " (built without OpenMP: serial)")
              << ", MPI ranks = " << ranks << '\n';
}

} // namespace

CLI::App* addThrowCommand(CLI::App& app, ThrowOptions& options)
{
    CLI::App* command = app.add_subcommand(
        "throw", "Throw a scenario's dice many times and count the faces they come to rest on");
    command->add_option("FILE", options.file, "Scenario file (TOML) with a [throw] table")
        ->required()
        ->type_name("");
    command->add_option("--throws", options.throws, "Number of throws (>= 1, default 1000)")
        ->type_name("N")
        ->check(wholeNumberIn(1, std::numeric_limits<std::int64_t>::max() / 2));
    command->add_option("--seed", options.seed, "Seed of the draws (default 1)")
        ->type_name("S")
        ->check(seedNumber());
    addThreadsOption(command, options.threads,
                     "Threads (default 0: one per core, at most " + std::to_string(kMaxThreads) +
                         ")");
    command->add_option("--csv", options.csvPath, "Write one row per throw to this CSV file")
        ->type_name("PATH");
    command->add_option("--summary-json", options.summaryJsonPath,
                        "Write the face counts as JSON to this file")
        ->type_name("PATH");
    command->add_option("--replay", options.replay,
                        "Write throw I as an ordinary scenario file (with --out) and stop")
        ->type_name("I")
        ->check(wholeNumberIn(0, std::numeric_limits<std::int64_t>::max()));
    command->add_option("--out", options.outPath, "The scenario file --replay writes")
        ->type_name("THROW.toml");
    command->add_option("--set", options.overrides,
                        "Override a scenario value, KEY=VALUE (throw.max_time=5, "
                        "die.friction=0.3); repeatable")
        ->type_name("KEY=VALUE")
        ->allow_extra_args(false);
    return command;
}

/// Issue 14, item 14: a throw run stopped by a signal prints and writes the face counts of the
/// throws it finished, marked as interrupted (the CSV, a row per throw, is not written).
int reportInterruptedThrows(const ThrowOptions& options, const scenario::Scenario& loaded,
                            const MpiSession& mpi,
                            std::span<const scenario::ThrowOutcome> block,
                            std::span<const std::uint8_t> finished)
{
    std::vector<scenario::ThrowOutcome> done;
    for (std::size_t i = 0; i < block.size(); ++i) {
        if (finished[i] != 0) {
            done.push_back(block[i]);
        }
    }
    FaceCounts faces = countFaces(done);
    mpi.sumToRoot(faces.counts);
    const int signal = InterruptGuard::received();
    if (mpi.isRoot()) {
        const std::int64_t total = faces.settled() + faces.unsettled();
        printError(std::string("interrupted by ") + signalName(signal != 0 ? signal : 2) +
                   " after " + std::to_string(total) + " of " + std::to_string(options.throws) +
                   " throws; the counts below are of those " + std::to_string(total) +
                   (options.csvPath.empty() ? "" : "; no CSV written"));
        printFaceTable(std::cout, loaded, faces);
        if (!options.summaryJsonPath.empty()) {
            OutputFile json(options.summaryJsonPath);
            const std::string text = summaryJson(total, faces, options.seed, true);
            std::fwrite(text.data(), 1, text.size(), json.handle());
            json.finish();
        }
    }
    return kExitSignalBase + (signal != 0 ? signal : 2);
}

int throwCommand(const ThrowOptions& options)
{
    if ((options.replay >= 0) != !options.outPath.empty()) {
        throw scenario::ScenarioError(scenario::SourceLocation{"tumble throw", 0}, "--replay",
                                      "--replay I and --out THROW.toml go together");
    }
    checkDistinctPaths(options.file, {{"--csv", options.csvPath},
                                      {"--summary-json", options.summaryJsonPath},
                                      {"--out", options.outPath}});
    const MpiSession mpi;
    const scenario::Scenario loaded = loadThrowScenario(options);
    if (!singleDieThrow(loaded)) {
        if (options.replay >= 0) {
            return mpi.isRoot() ? writeDiceReplay(options, loaded) : kExitOk;
        }
        return throwDiceCommand(options, loaded, mpi);
    }
    if (options.replay >= 0) {
        return mpi.isRoot() ? writeReplay(options, loaded) : kExitOk;
    }

    const int threads = parallelBuild() ? (options.threads > 0 ? options.threads
                                                               : defaultThreadCount())
                                        : 1;
    if (mpi.isRoot()) {
        printHeader(options, loaded, threads, mpi.size());
        std::cout.flush();
    }

    // this rank's contiguous block of throws
    const std::int64_t begin = mpi.blockBegin(options.throws);
    const std::int64_t end = mpi.blockEnd(options.throws);
    std::vector<scenario::ThrowOutcome> block(static_cast<std::size_t>(end - begin));
    std::vector<std::uint8_t> finished(block.size(), 0);
    const bool progress = mpi.isRoot() && isatty(STDERR_FILENO) != 0;
    const InterruptGuard interruptGuard;
    const auto start = std::chrono::steady_clock::now();
    const std::int64_t run =
        runThrows(loaded, options.seed, begin, block, finished, threads, progress, options.throws);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!mpi.allOk(run == end - begin)) {
        return reportInterruptedThrows(options, loaded, mpi, block, finished);
    }

    // face counts are integers, so their sum does not depend on the order of the ranks
    FaceCounts faces = countFaces(block);
    mpi.sumToRoot(faces.counts);
    std::vector<scenario::ThrowOutcome> all;
    if (!options.csvPath.empty()) {
        all.resize(mpi.isRoot() ? static_cast<std::size_t>(options.throws) : 0);
        mpi.gatherToRoot(block, all, options.throws);
    }
    if (!mpi.isRoot()) {
        return kExitOk;
    }
    printFaceTable(std::cout, loaded, faces);
    char timing[128];
    std::snprintf(timing, sizeof timing, "time: %.3f s (%.0f throws/s)\n", seconds,
                  static_cast<double>(options.throws) / (seconds > 0.0 ? seconds : 1e-9));
    std::cout << timing;
    if (!options.summaryJsonPath.empty()) {
        OutputFile json(options.summaryJsonPath);
        const std::string text = summaryJson(options.throws, faces, options.seed);
        std::fwrite(text.data(), 1, text.size(), json.handle());
        json.finish();
    }
    if (!options.csvPath.empty()) {
        writeThrowCsv(options.csvPath, loaded, options.seed, all);
    }
    return kExitOk;
}

} // namespace tumble::cli
