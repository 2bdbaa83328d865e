// Running a block of throws on K threads (OpenMP, a fixed chunking) with an optional progress bar.
#include "throw_batch.hpp"

#include "cli_options.hpp"
#include "interrupt.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>

#if TUMBLE_HAS_OPENMP
#include <omp.h>
#endif

namespace tumble::cli {
namespace {

using Clock = std::chrono::steady_clock;

/// Seconds between redraws of the progress bar.
constexpr double kRedrawInterval = 0.2;
constexpr int kBarWidth = 30;

/// The one-line bar on stderr, redrawn in place with a carriage return.
class ProgressBar {
public:
    ProgressBar(std::int64_t blockSize, std::int64_t totalThrows)
        : m_blockSize(blockSize), m_scale(static_cast<double>(totalThrows) /
                                          static_cast<double>(blockSize > 0 ? blockSize : 1)),
          m_start(Clock::now()), m_lastDraw(m_start)
    {
    }

    /// Redraws when kRedrawInterval has passed since the last time (or when forced).
    void update(std::int64_t done, bool force = false)
    {
        const Clock::time_point now = Clock::now();
        if (!force && std::chrono::duration<double>(now - m_lastDraw).count() < kRedrawInterval) {
            return;
        }
        m_lastDraw = now;
        const double elapsed = std::chrono::duration<double>(now - m_start).count();
        const double fraction =
            m_blockSize > 0 ? static_cast<double>(done) / static_cast<double>(m_blockSize) : 1.0;
        const double rate = elapsed > 0.0 ? static_cast<double>(done) * m_scale / elapsed : 0.0;
        const double left = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
        char bar[kBarWidth + 1];
        const int filled = static_cast<int>(fraction * kBarWidth);
        for (int i = 0; i < kBarWidth; ++i) {
            bar[i] = i < filled ? '#' : '.';
        }
        bar[kBarWidth] = '\0';
        std::fprintf(stderr, "\r[%s] %lld/%lld throws  %.0f throws/s  %.1f s left  ", bar,
                     static_cast<long long>(static_cast<double>(done) * m_scale),
                     static_cast<long long>(static_cast<double>(m_blockSize) * m_scale), rate,
                     left);
        std::fflush(stderr);
    }

    /// Clears the line so the report starts on a clean one.
    static void clear()
    {
        std::fprintf(stderr, "\r\033[K");
        std::fflush(stderr);
    }

private:
    std::int64_t m_blockSize;
    double m_scale;
    Clock::time_point m_start;
    Clock::time_point m_lastDraw;
};

} // namespace

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
    ProgressBar bar(count, totalThrows);
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
