// A barrier between the threads of one parallel region that waits by spinning (parallel_for.hpp).
#pragma once

#include <atomic>
#include <thread>

namespace tumble {

/// The threads of a region meet here between phases of a few microseconds (the colours of a
/// soft island's passes, (12.9)), where an OpenMP barrier costs about three times as long as a
/// counter in shared memory: each arrival counts itself, the last one opens the next
/// generation, the others spin on it. A waiting thread yields after a while, so that more
/// threads than cores still progress.
class SpinBarrier {
public:
    /// The threads that meet: each of them says so before its first wait, all with the same
    /// count (the region's team size).
    void setThreads(int threads) { m_threads.store(threads, std::memory_order_relaxed); }

    void wait()
    {
        const int generation = m_generation.load(std::memory_order_acquire);
        if (m_arrived.fetch_add(1, std::memory_order_acq_rel) + 1 ==
            m_threads.load(std::memory_order_relaxed)) {
            m_arrived.store(0, std::memory_order_relaxed);
            m_generation.store(generation + 1, std::memory_order_release);
            return;
        }
        for (int spins = 0; m_generation.load(std::memory_order_acquire) == generation;
             ++spins) {
            if (spins < kSpinsBeforeYield) {
                relax();
            } else {
                std::this_thread::yield();
            }
        }
    }

private:
    static constexpr int kSpinsBeforeYield = 4000;

    /// Tells the core this is a wait loop (it frees the pipeline for the other thread).
    static void relax()
    {
#if defined(__x86_64__) || defined(__i386__)
        __builtin_ia32_pause();
#endif
    }

    std::atomic<int> m_threads{1};
    alignas(64) std::atomic<int> m_arrived{0};
    alignas(64) std::atomic<int> m_generation{0};
};

} // namespace tumble
