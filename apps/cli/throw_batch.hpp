// `tumble throw`'s batches: the library's runThrowBatch (tumble/scenario/throw_batch.hpp) with
// the CLI's signal handling (InterruptGuard) and progress bar on stderr.
#pragma once

#include "tumble/scenario/scenario.hpp"
#include "tumble/scenario/throw.hpp"
#include "tumble/scenario/throw_dice.hpp"

#include <cstdint>
#include <span>

namespace tumble::cli {

/// Threads to use when --threads is not given: every core OpenMP sees (1 without OpenMP), at
/// most kMaxThreads.
int defaultThreadCount();
/// Whether this build runs throws in parallel (OpenMP was found).
bool parallelBuild();

/// Runs throws firstIndex .. firstIndex + outcomes.size() - 1 into `outcomes` on `threads`
/// threads. With `progress`, draws a bar on stderr (throws done, throws/s, time left), scaled to
/// `totalThrows` when this is one of several equal blocks (MPI ranks). Stops early when SIGINT
/// or SIGTERM arrives; `finished[i]` is set for each throw that ran. Returns their number.
std::int64_t runThrows(const scenario::Scenario& scenario, std::uint64_t seed,
                       std::int64_t firstIndex, std::span<scenario::ThrowOutcome> outcomes,
                       std::span<std::uint8_t> finished,
                       int threads, bool progress, std::int64_t totalThrows);

/// The same for a scenario of several dice (scenario::runDiceBatch): `outcomes` holds one
/// DieOutcome per die of each throw.
std::int64_t runDiceThrows(const scenario::Scenario& scenario, std::uint64_t seed,
                           std::int64_t firstIndex, std::span<scenario::DieOutcome> outcomes,
                           std::span<std::uint8_t> finished, int threads, bool progress,
                           std::int64_t totalThrows);

} // namespace tumble::cli
