// `tumble throw` for a scenario of several dice: each rank runs its block of throws, the integer
// counts are summed over the ranks (so the report does not depend on threads or ranks), and rank
// 0 prints and writes.
#include "throw_dice_command.hpp"

#include "console.hpp"
#include "dice_report.hpp"
#include "interrupt.hpp"
#include "output_file.hpp"
#include "throw_batch.hpp"

#include "tumble/scenario/throw_batch.hpp"
#include "tumble/scenario/throw_dice.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <iostream>

namespace tumble::cli {

namespace {

/// Throws whose placement the loader checks: enough to catch a region or cluster too small for
/// the dice, few enough to cost nothing.
constexpr std::uint64_t kPlacementChecks = 16;

void printDiceHeader(const ThrowOptions& options, const scenario::Scenario& loaded, int threads,
                     int ranks)
{
    std::cout << "scenario: " << options.file << '\n';
    for (const std::size_t body : scenario::diceOf(loaded)) {
        const BodyDef& die = loaded.bodies[body].def;
        std::cout << "die " << loaded.bodies[body].name
                  << ": size = " << formatVec3(die.shape.size)
                  << " m, mass = " << formatFixed(die.mass)
                  << " kg, elasticity = " << formatFixed(die.material.restitution)
                  << ", friction = " << formatFixed(die.material.friction) << '\n';
    }
    std::cout << "throws = " << options.throws << ", seed = " << options.seed
              << ", threads = " << threads
              << (parallelBuild() ? "" : " (built without OpenMP: serial)")
              << ", MPI ranks = " << ranks << '\n';
}

DiceCounts countDice(const scenario::Scenario& loaded, std::span<const scenario::DieOutcome> block,
                     std::span<const std::uint8_t> finished)
{
    const std::size_t dice = scenario::diceOf(loaded).size();
    DiceCounts counts(dice, allCubes(loaded));
    for (std::size_t i = 0; i < finished.size(); ++i) {
        if (finished[i] != 0) {
            counts.add(block.subspan(i * dice, dice));
        }
    }
    return counts;
}

void writeJson(const std::string& path, const std::string& text)
{
    OutputFile json(path);
    std::fwrite(text.data(), 1, text.size(), json.handle());
    json.finish();
}

/// Rank 0's part: the report, the JSON and the CSV. `seconds` < 0 marks a run stopped by a
/// signal, whose counts are of the throws that finished and whose CSV is not written.
int reportDice(const ThrowOptions& options, const scenario::Scenario& loaded,
               const DiceCounts& counts, std::span<const scenario::DieOutcome> all, double seconds)
{
    const bool complete = seconds >= 0.0;
    const int signal = InterruptGuard::received();
    if (!complete) {
        printError(std::string("interrupted by ") + signalName(signal != 0 ? signal : 2) +
                   " after " + std::to_string(counts.throws()) + " of " +
                   std::to_string(options.throws) + " throws; the counts below are of those" +
                   (options.csvPath.empty() ? "" : "; no CSV written"));
    }
    printDiceReport(std::cout, loaded, counts);
    if (complete) {
        char timing[128];
        std::snprintf(timing, sizeof timing, "time: %.3f s (%.0f throws/s)\n", seconds,
                      static_cast<double>(options.throws) / (seconds > 0.0 ? seconds : 1e-9));
        std::cout << timing;
    }
    if (!options.summaryJsonPath.empty()) {
        writeJson(options.summaryJsonPath,
                  diceSummaryJson(loaded, complete ? options.throws : counts.throws(), counts,
                                  options.seed, !complete));
    }
    if (complete && !options.csvPath.empty()) {
        writeDiceCsv(options.csvPath, loaded, all);
    }
    return complete ? kExitOk : kExitSignalBase + (signal != 0 ? signal : 2);
}

} // namespace

bool singleDieThrow(const scenario::Scenario& scenario)
{
    const scenario::ThrowSpec& spec = *scenario.throwSpec;
    return scenario.bodies.size() == 1 && scenario.ground && !spec.region &&
           spec.release == scenario::ThrowRelease::Each;
}

void checkDicePlacement(const ThrowOptions& options, const scenario::Scenario& loaded)
{
    for (std::uint64_t index = 0; index < kPlacementChecks; ++index) {
        std::vector<bool> placed;
        (void)scenario::drawDice(loaded, options.seed, index, &placed);
        for (std::size_t k = 0; k < placed.size(); ++k) {
            if (!placed[k]) {
                throw scenario::ScenarioError(
                    scenario::SourceLocation{options.file, 0}, "throw.region",
                    "die " + std::to_string(k + 1) + " of throw " + std::to_string(index) +
                        " overlaps the static geometry or another die in " +
                        std::to_string(scenario::kPlacementAttempts) +
                        " draws: give the dice more room (a larger region or cluster_radius)");
            }
        }
    }
}

int throwDiceCommand(const ThrowOptions& options, const scenario::Scenario& loaded,
                     const MpiSession& mpi)
{
    const int threads = parallelBuild() ? (options.threads > 0 ? options.threads
                                                               : defaultThreadCount())
                                        : 1;
    if (mpi.isRoot()) {
        printDiceHeader(options, loaded, threads, mpi.size());
        std::cout.flush();
    }
    const std::size_t dice = scenario::diceOf(loaded).size();
    const std::int64_t begin = mpi.blockBegin(options.throws);
    const std::int64_t end = mpi.blockEnd(options.throws);
    const auto throws = static_cast<std::size_t>(end - begin);
    std::vector<scenario::DieOutcome> block(throws * dice);
    std::vector<std::uint8_t> finished(throws, 0);
    const bool progress = mpi.isRoot() && isatty(STDERR_FILENO) != 0;
    const InterruptGuard interruptGuard;
    const auto start = std::chrono::steady_clock::now();
    const std::int64_t run = runDiceThrows(loaded, options.seed, begin, block, finished, threads,
                                           progress, options.throws);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    // the counts are integers, so their sum does not depend on the order of the ranks
    DiceCounts counts = countDice(loaded, block, finished);
    mpi.sumToRoot(counts.data());
    const bool complete = mpi.allOk(run == end - begin);
    std::vector<scenario::DieOutcome> all;
    if (complete && !options.csvPath.empty()) {
        all.resize(mpi.isRoot() ? static_cast<std::size_t>(options.throws) * dice : 0);
        mpi.gatherToRoot(block, all, options.throws, dice);
    }
    if (!mpi.isRoot()) {
        return complete ? kExitOk : kExitSignalBase + 2;
    }
    return reportDice(options, loaded, counts, all, complete ? seconds : -1.0);
}

int writeDiceReplay(const ThrowOptions& options, const scenario::Scenario& loaded)
{
    const auto index = static_cast<std::uint64_t>(options.replay);
    const std::vector<scenario::ThrowState> states =
        scenario::drawDice(loaded, options.seed, index);
    const std::string comment =
        "Throw " + std::to_string(index) + " of " + options.file + " with seed " +
        std::to_string(options.seed) + ", written by `tumble throw " + options.file + " --seed " +
        std::to_string(options.seed) + " --replay " + std::to_string(index) +
        "`.\n`tumble run` on this file reproduces the throw: every die on the same face at the "
        "same rest time.";
    OutputFile output(options.outPath);
    const std::string text = scenario::diceScenarioToml(loaded, states, comment);
    std::fwrite(text.data(), 1, text.size(), output.handle());
    output.finish();

    const std::vector<std::size_t> dice = scenario::diceOf(loaded);
    std::vector<scenario::DieOutcome> outcomes(dice.size());
    scenario::runDiceThrow(loaded, options.seed, index, outcomes);
    std::cout << "throw " << index << " written to " << options.outPath << '\n';
    for (std::size_t k = 0; k < dice.size(); ++k) {
        const scenario::DieOutcome& die = outcomes[k];
        std::cout << "die " << loaded.bodies[dice[k]].name << ": ";
        if (die.settled != 0) {
            std::cout << "at rest at t = " << formatFull(die.restTime) << " s on face "
                      << faceName(static_cast<CuboidFace>(die.face))
                      << (die.cocked != 0 ? " (cocked)" : "") << '\n';
        } else {
            std::cout << "not at rest by max_time = " << formatFull(loaded.throwSpec->maxTime)
                      << " s\n";
        }
    }
    return kExitOk;
}

} // namespace tumble::cli
