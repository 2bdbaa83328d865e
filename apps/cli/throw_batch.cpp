// Running a block of throws on K threads (OpenMP, a fixed chunking) with an optional progress bar.
#include "throw_batch.hpp"

#include "cli_options.hpp"
#include "interrupt.hpp"
#include "progress_bar.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>

#if TUMBLE_HAS_OPENMP
#include <omp.h>
#endif

namespace tumble::cli {

int defaultThreadCount()
{
#if TUMBLE_HAS_OPENMP
    return std::clamp(omp_get_num_procs(), 1, kMaxThreads);
#else
    return 1;
#endif
}

bool parallelBuild()
{
#if TUMBLE_HAS_OPENMP
    return true;
#else
    return false;
#endif
}

std::int64_t runThrows(const scenario::Scenario& scenario, std::uint64_t seed,
                       std::int64_t firstIndex, std::span<scenario::ThrowOutcome> outcomes,
                       std::span<std::uint8_t> finished, int threads, bool progress,
                       std::int64_t totalThrows)
{
    const auto count = static_cast<std::int64_t>(outcomes.size());
    std::atomic<std::int64_t> done{0};
    ProgressBar bar(count, totalThrows, "throws");
    (void)threads;

    // each throw has its own World and generator; thread 0 also draws the bar. A signal skips
    // the throws not yet started (an OpenMP loop cannot break).
#if TUMBLE_HAS_OPENMP
#pragma omp parallel for schedule(static, kThrowsPerChunk) num_threads(threads)
#endif
    for (std::int64_t i = 0; i < count; ++i) {
        if (InterruptGuard::received() != 0) {
            continue;
        }
        const std::uint64_t index = static_cast<std::uint64_t>(firstIndex + i);
        outcomes[static_cast<std::size_t>(i)] =
            scenario::runThrow(scenario, scenario::drawThrow(scenario, seed, index));
        finished[static_cast<std::size_t>(i)] = 1;
        const std::int64_t finishedCount = done.fetch_add(1, std::memory_order_relaxed) + 1;
#if TUMBLE_HAS_OPENMP
        const bool drawer = omp_get_thread_num() == 0;
#else
        const bool drawer = true;
#endif
        if (progress && drawer) {
            bar.update(finishedCount);
        }
    }
    if (progress) {
        bar.update(done.load(), true);
        ProgressBar::clear();
    }
    return done.load();
}

} // namespace tumble::cli
