// Loops whose iterations write disjoint state, spread over threads (OpenMP where built with it).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <utility>

#include "spin_barrier.hpp"

#ifdef TUMBLE_HAVE_OPENMP
#include <omp.h>
#endif

namespace tumble {

/// Calls `body(i)` for each i in [0, count), over `threads` threads in a static schedule when
/// threads > 1. Each call must write only what no other call reads or writes, so the result is
/// the same for any number of threads (11.5c).
template <typename Body>
void parallelFor(std::size_t count, [[maybe_unused]] int threads, const Body& body)
{
#ifdef TUMBLE_HAVE_OPENMP
    if (threads > 1 && count > 1) {
        const auto signedCount = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(static) num_threads(threads)
        for (std::ptrdiff_t i = 0; i < signedCount; ++i) {
            body(static_cast<std::size_t>(i));
        }
        return;
    }
#endif
    for (std::size_t i = 0; i < count; ++i) {
        body(i);
    }
}

/// parallelFor for iterations of unequal cost: `chunk` iterations at a time go to whichever
/// thread is free. Each call must write only what no other call reads or writes, so the result
/// is the same for any number of threads and any hand-out (11.5c).
template <typename Body>
void parallelForBalanced(std::size_t count, int threads, std::size_t chunk, const Body& body)
{
    const std::size_t chunks = (count + chunk - 1) / chunk;
    std::atomic<std::size_t> next{0};
    // one call a thread, each taking the next chunk until none is left
    parallelFor(static_cast<std::size_t>(std::max(threads, 1)), threads, [&](std::size_t) {
        for (std::size_t c = next++; c < chunks; c = next++) {
            const std::size_t last = std::min(count, (c + 1) * chunk);
            for (std::size_t i = c * chunk; i < last; ++i) {
                body(i);
            }
        }
    });
}

/// One thread of a team running in one parallel region (parallelTeam): its index among the
/// team's threads, and the barrier they meet at.
class PhaseTeam {
public:
    PhaseTeam(std::size_t share, std::size_t shares, SpinBarrier* barrier)
        : m_share(share), m_shares(shares), m_barrier(barrier)
    {
    }

    [[nodiscard]] std::size_t share() const { return m_share; }
    [[nodiscard]] std::size_t shares() const { return m_shares; }
    /// Returns when every thread of the team has called it (at once with one thread): what
    /// the team wrote before is then read by any of them.
    void sync() const
    {
        if (m_barrier != nullptr) {
            m_barrier->wait();
        }
    }

private:
    std::size_t m_share;
    std::size_t m_shares;
    SpinBarrier* m_barrier;
};

/// Calls `body(team)` on each of `threads` threads in one parallel region, each with its
/// PhaseTeam; with one thread, once with a team of one. The body's phases meet at team.sync(),
/// which costs a counter's round trip between the cores where starting a region costs several
/// (11.5c).
template <typename Body>
void parallelTeam([[maybe_unused]] int threads, const Body& body)
{
#ifdef TUMBLE_HAVE_OPENMP
    if (threads > 1) {
        SpinBarrier barrier;
#pragma omp parallel num_threads(threads)
        {
            const auto share = static_cast<std::size_t>(omp_get_thread_num());
            const auto shares = static_cast<std::size_t>(omp_get_num_threads());
            barrier.setThreads(static_cast<int>(shares));
            body(PhaseTeam(share, shares, shares > 1 ? &barrier : nullptr));
        }
        return;
    }
#endif
    body(PhaseTeam(0, 1, nullptr));
}

/// Calls `body(phase, share, shares)` for each phase in [0, phases), in order, on each of
/// `threads` threads (`share` the thread's index among the `shares` that run), every thread
/// ending a phase before any begins the next: one parallel region for all the phases and a
/// barrier between them, where a region per phase would start the threads again each time.
/// With one thread, body(phase, 0, 1) for each phase. What a phase writes must not depend on
/// how its work is shared for the result to be the same for any number of threads (11.5c).
template <typename Body>
void parallelPhases(std::size_t phases, int threads, const Body& body)
{
    if (phases == 0) {
        return;
    }
    parallelTeam(threads, [&](const PhaseTeam& team) {
        for (std::size_t phase = 0; phase < phases; ++phase) {
            body(phase, team.share(), team.shares());
            // the region's end waits for every thread after the last phase
            if (phase + 1 < phases) {
                team.sync();
            }
        }
    });
}

/// The iterations [first, last) of thread `share` of `shares` in the two fixed shares of
/// parallelForSplit: [0, split) for the first, [split, count) for the second, all of them for a
/// thread alone, none for a third.
inline std::pair<std::size_t, std::size_t> splitShare(std::size_t count, std::size_t split,
                                                      std::size_t share, std::size_t shares)
{
    const std::size_t first = share == 0 ? 0 : (share == 1 ? split : count);
    const std::size_t last = share == 0 && shares > 1 ? split : count;
    return {first, last};
}

/// parallelFor with the iterations in two fixed shares: [0, split) on the first thread and
/// [split, count) on the second (any further thread idle), where threads > 1 and
/// 0 < split < count; else parallelFor. For loops over data the same two threads work on in
/// the same shares elsewhere (a soft island's halves, (12.9)), so that it stays in their caches.
template <typename Body>
void parallelForSplit(std::size_t count, std::size_t split, int threads, const Body& body)
{
    if (split == 0 || split >= count || threads < 2) {
        parallelFor(count, threads, body);
        return;
    }
    parallelPhases(1, 2, [&](std::size_t, std::size_t share, std::size_t shares) {
        const auto [first, last] = splitShare(count, split, share, shares);
        for (std::size_t i = first; i < last; ++i) {
            body(i);
        }
    });
}

/// Whether `holds(i)` for some i in [0, count), each i tested on one of `threads` threads in a
/// static schedule when threads > 1. The answer does not depend on the number of threads.
template <typename Predicate>
bool parallelAnyOf(std::size_t count, [[maybe_unused]] int threads, const Predicate& holds)
{
#ifdef TUMBLE_HAVE_OPENMP
    if (threads > 1 && count > 1) {
        const auto signedCount = static_cast<std::ptrdiff_t>(count);
        bool found = false;
#pragma omp parallel for schedule(static) num_threads(threads) reduction(|| : found)
        for (std::ptrdiff_t i = 0; i < signedCount; ++i) {
            found = found || holds(static_cast<std::size_t>(i));
        }
        return found;
    }
#endif
    for (std::size_t i = 0; i < count; ++i) {
        if (holds(i)) {
            return true;
        }
    }
    return false;
}

} // namespace tumble
