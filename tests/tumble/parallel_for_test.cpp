// The loops over threads hand out every item once, and the phases end before the next begins,
// whatever the number of threads (libs/tumble/src/parallel_for.hpp, (11.5c)).
#include "parallel_for.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <vector>

namespace tumble {
namespace {

TEST(ParallelFor, BalancedHandOutVisitsEveryItemOnce)
{
    for (const int threads : {1, 2, 3}) {
        for (const std::size_t chunk : {1u, 7u, 64u}) {
            std::vector<std::atomic<int>> visits(1000);
            parallelForBalanced(visits.size(), threads, chunk,
                                [&](std::size_t i) { visits[i].fetch_add(1); });
            for (std::size_t i = 0; i < visits.size(); ++i) {
                ASSERT_EQ(visits[i].load(), 1) << "item " << i << ", " << threads
                                               << " threads, chunks of " << chunk;
            }
        }
    }
}

TEST(ParallelFor, EachPhaseSeesTheWholeOfThePreviousOne)
{
    // phase p writes each item as p + 1, split over the shares; phase p + 1 reads every item
    // (other shares' too) and counts those not yet at p + 1: a phase begun before the last one
    // ended would find some
    constexpr std::size_t items = 4096;
    constexpr std::size_t phases = 200;
    // more threads than cores too: a waiting thread must give way to those still at work
    for (const int threads : {1, 2, 4, 8}) {
        std::vector<std::atomic<std::size_t>> value(items);
        std::atomic<std::size_t> early{0};
        std::atomic<std::size_t> written{0};
        parallelPhases(phases, threads, [&](std::size_t phase, std::size_t share,
                                            std::size_t shares) {
            ASSERT_LT(share, shares);
            const std::size_t first = share * items / shares;
            const std::size_t last = (share + 1) * items / shares;
            for (std::size_t i = 0; i < items; ++i) {
                early += value[i].load() < phase ? 1 : 0;
            }
            for (std::size_t i = first; i < last; ++i) {
                value[i].store(phase + 1);
                ++written;
            }
        });
        EXPECT_EQ(early.load(), 0u) << threads << " threads";
        EXPECT_EQ(written.load(), items * phases) << threads << " threads";
        for (std::size_t i = 0; i < items; ++i) {
            ASSERT_EQ(value[i].load(), phases);
        }
    }
}

} // namespace
} // namespace tumble
