// Running a block of throws on K threads (OpenMP, a fixed chunking).
#include "tumble/scenario/throw_batch.hpp"

#include <atomic>

#if TUMBLE_HAS_OPENMP
#include <omp.h>
#endif

namespace tumble::scenario {

bool parallelThrowBuild()
{
#if TUMBLE_HAS_OPENMP
    return true;
#else
    return false;
#endif
}

int throwCoreCount()
{
#if TUMBLE_HAS_OPENMP
    return omp_get_num_procs();
#else
    return 1;
#endif
}

namespace {

/// Runs `runOne(i)` for i in [0, count) on `threads` threads with the hooks; returns how many ran.
template <typename RunOne>
std::int64_t runBatch(std::int64_t count, std::span<std::uint8_t> finished, int threads,
                      const ThrowBatchHooks& hooks, const RunOne& runOne)
{
    std::atomic<std::int64_t> done{0};
    (void)threads;

    // each throw has its own World and generator; thread 0 (the caller) also reports progress
#if TUMBLE_HAS_OPENMP
#pragma omp parallel for schedule(static, kThrowsPerChunk) num_threads(threads)
#endif
    for (std::int64_t i = 0; i < count; ++i) {
        if (hooks.stopRequested && hooks.stopRequested()) {
            continue;
        }
        runOne(i);
        finished[static_cast<std::size_t>(i)] = 1;
        const std::int64_t finishedCount = done.fetch_add(1, std::memory_order_relaxed) + 1;
#if TUMBLE_HAS_OPENMP
        const bool caller = omp_get_thread_num() == 0;
#else
        const bool caller = true;
#endif
        if (caller && hooks.progress) {
            hooks.progress(finishedCount);
        }
    }
    return done.load();
}

} // namespace

std::int64_t runThrowBatch(const Scenario& scenario, std::uint64_t seed, std::int64_t firstIndex,
                           std::span<ThrowOutcome> outcomes, std::span<std::uint8_t> finished,
                           int threads, const ThrowBatchHooks& hooks)
{
    return runBatch(static_cast<std::int64_t>(outcomes.size()), finished, threads, hooks,
                    [&](std::int64_t i) {
                        const auto index = static_cast<std::uint64_t>(firstIndex + i);
                        outcomes[static_cast<std::size_t>(i)] =
                            runThrow(scenario, drawThrow(scenario, seed, index));
                    });
}

std::int64_t runDiceBatch(const Scenario& scenario, std::uint64_t seed, std::int64_t firstIndex,
                          std::span<DieOutcome> outcomes, std::span<std::uint8_t> finished,
                          int threads, const ThrowBatchHooks& hooks)
{
    const std::size_t dice = diceOf(scenario).size();
    return runBatch(static_cast<std::int64_t>(finished.size()), finished, threads, hooks,
                    [&](std::int64_t i) {
                        const auto index = static_cast<std::uint64_t>(firstIndex + i);
                        runDiceThrow(scenario, seed, index,
                                     outcomes.subspan(static_cast<std::size_t>(i) * dice, dice));
                    });
}

} // namespace tumble::scenario
