// Running a block of throws on K threads (OpenMP, a fixed chunking); each throw depends only on
// (seed, index), so the outcomes do not depend on K. The CLI and the Python module both run their
// throws here and differ only in how they stop and show progress (ThrowBatchHooks).
#pragma once

#include "tumble/scenario/scenario.hpp"
#include "tumble/scenario/throw.hpp"
#include "tumble/scenario/throw_dice.hpp"

#include <cstdint>
#include <functional>
#include <span>

namespace tumble::scenario {

/// Throws handed to a thread at a time, in round robin: fixed, so the split does not depend on
/// timing (the outcomes would not anyway).
constexpr int kThrowsPerChunk = 16;

/// Whether this build runs throws in parallel (OpenMP was found).
bool parallelThrowBuild();
/// The cores OpenMP sees (1 without OpenMP).
int throwCoreCount();

/// How a caller watches a batch. Both may be empty.
struct ThrowBatchHooks {
    /// Asked before each throw on every thread (so it must be thread-safe): true skips the throws
    /// not yet started (an OpenMP loop cannot break).
    std::function<bool()> stopRequested;
    /// Called on the calling thread only (OpenMP's thread 0) after each of its throws, with the
    /// number of throws finished on all threads so far.
    std::function<void(std::int64_t)> progress;
};

/// Runs throws firstIndex .. firstIndex + outcomes.size() - 1 into `outcomes` on `threads`
/// threads (>= 1). `finished[i]` is set for each throw that ran. Returns their number.
std::int64_t runThrowBatch(const Scenario& scenario, std::uint64_t seed, std::int64_t firstIndex,
                           std::span<ThrowOutcome> outcomes, std::span<std::uint8_t> finished,
                           int threads, const ThrowBatchHooks& hooks = {});

/// The same for a scenario of several dice: throw firstIndex + i fills outcomes[i * n ..
/// i * n + n - 1], n = diceOf(scenario).size() (runDiceThrow).
std::int64_t runDiceBatch(const Scenario& scenario, std::uint64_t seed, std::int64_t firstIndex,
                          std::span<DieOutcome> outcomes, std::span<std::uint8_t> finished,
                          int threads, const ThrowBatchHooks& hooks = {});

} // namespace tumble::scenario
