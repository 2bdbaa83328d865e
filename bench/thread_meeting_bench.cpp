// What two threads pay to meet on this machine (docs/benchmark.md, "Two threads: one region for
// the sub-steps"): a cache line's round trip between two cores, a meeting at the spinning barrier
// the soft step's passes use, and the start and end of a parallel region. The soft step's second
// thread gains only where a pass's work outweighs these.
#include "parallel_for.hpp"

#include <benchmark/benchmark.h>

#include <atomic>
#include <cstdint>
#include <thread>

#ifdef __linux__
#include <pthread.h>
#include <sched.h>
#endif

namespace tumble {
namespace {

/// Runs the calling thread on core `core` only, where the system lets it; returns whether it
/// does.
bool pinToCore([[maybe_unused]] int core)
{
#ifdef __linux__
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(core, &set);
    return pthread_setaffinity_np(pthread_self(), sizeof(set), &set) == 0;
#else
    return false;
#endif
}

/// Lets the calling thread run on any core again.
void unpin()
{
#ifdef __linux__
    cpu_set_t set;
    CPU_ZERO(&set);
    for (unsigned core = 0; core < std::thread::hardware_concurrency(); ++core) {
        CPU_SET(core, &set);
    }
    pthread_setaffinity_np(pthread_self(), sizeof(set), &set);
#endif
}

/// One iteration: this thread (core 0) writes an odd count to a line, the partner (core 1)
/// spins until it sees it and writes the next count, this thread spins until it sees that.
void coreRoundTrip(benchmark::State& state)
{
    if (std::thread::hardware_concurrency() < 2) {
        state.SkipWithError("needs two cores");
        return;
    }
    alignas(64) std::atomic<std::int64_t> line{0};
    alignas(64) std::atomic<bool> stop{false};
    std::thread partner([&] {
        pinToCore(1);
        std::int64_t answered = 0;
        while (!stop.load(std::memory_order_relaxed)) {
            const std::int64_t seen = line.load(std::memory_order_acquire);
            if (seen != answered && seen % 2 == 1) {
                answered = seen + 1;
                line.store(answered, std::memory_order_release);
            }
        }
    });
    pinToCore(0);
    std::int64_t sent = 1;
    for (auto _ : state) {
        line.store(sent, std::memory_order_release);
        while (line.load(std::memory_order_acquire) != sent + 1) {
        }
        sent += 2;
    }
    stop.store(true, std::memory_order_relaxed);
    partner.join();
    unpin();
}
BENCHMARK(coreRoundTrip)->UseRealTime();

/// The meetings of two threads at the team's spinning barrier (spin_barrier.hpp), 1 000 an
/// iteration in one region; the time shown is a meeting's.
void spinBarrierMeeting(benchmark::State& state)
{
#ifndef TUMBLE_HAVE_OPENMP
    state.SkipWithError("built without OpenMP: one thread, nothing to meet");
    return;
#endif
    constexpr int kMeetings = 1000;
    for (auto _ : state) {
        parallelTeam(2, [&](const PhaseTeam& team) {
            for (int meeting = 0; meeting < kMeetings; ++meeting) {
                team.sync();
            }
        });
    }
    state.counters["meeting"] = benchmark::Counter(
        static_cast<double>(kMeetings), benchmark::Counter::kIsIterationInvariantRate |
                                            benchmark::Counter::kInvert);
}
BENCHMARK(spinBarrierMeeting)->UseRealTime();

/// An empty parallel region of two threads (OpenMP where built with it): its start and end,
/// which a soft step's pass paid before its sub-steps shared one region.
void parallelRegion(benchmark::State& state)
{
#ifndef TUMBLE_HAVE_OPENMP
    state.SkipWithError("built without OpenMP: no region to start");
    return;
#endif
    std::atomic<int> visits{0};
    for (auto _ : state) {
        parallelTeam(2, [&](const PhaseTeam&) { visits.fetch_add(1, std::memory_order_relaxed); });
    }
    benchmark::DoNotOptimize(visits.load());
}
BENCHMARK(parallelRegion)->UseRealTime();

} // namespace
} // namespace tumble
