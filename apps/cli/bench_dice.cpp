// The throughput rows of `tumble bench`: whole throws, each run until its dice rest.
#include "bench_dice.hpp"

#include "throw_batch.hpp"

#include "tumble/scenario/throw.hpp"
#include "tumble/scenario/throw_dice.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace tumble::cli {

namespace {

void printRow(const char* name, long throws, int threads, double seconds, long settled)
{
    const double rate = static_cast<double>(throws) / seconds;
    std::printf("%-4s %-16s %8ld %7d %10.3f %10.0f %9ld %14.1f\n", "D", name, throws, threads,
                seconds, rate, settled, 1e5 / rate);
}

} // namespace

void printDiceRow(const scenario::Scenario& die, long throws, int threads)
{
    std::vector<scenario::ThrowOutcome> outcomes(static_cast<std::size_t>(throws));
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::uint8_t> finished(outcomes.size(), 0);
    runThrows(die, 1, 0, outcomes, finished, threads, false, throws);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const long settled = std::count_if(outcomes.begin(), outcomes.end(),
                                       [](const scenario::ThrowOutcome& outcome) {
                                           return outcome.settled;
                                       });
    printRow("dice_cube", throws, threads, seconds, settled);
}

void printTrayRow(const scenario::Scenario& tray, long throws, int threads)
{
    const std::size_t dice = scenario::diceOf(tray).size();
    std::vector<scenario::DieOutcome> outcomes(static_cast<std::size_t>(throws) * dice);
    std::vector<std::uint8_t> finished(static_cast<std::size_t>(throws), 0);
    const auto start = std::chrono::steady_clock::now();
    runDiceThrows(tray, 1, 0, outcomes, finished, threads, false, throws);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    long settled = 0;
    for (std::size_t i = 0; i < outcomes.size(); i += dice) {
        settled += outcomes[i].settled;
    }
    printRow("dice_two_in_tray", throws, threads, seconds, settled);
}

} // namespace tumble::cli
