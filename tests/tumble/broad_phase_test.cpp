// Sort and sweep against all pairs, after small moves, teleports and shuffles
// (docs/decisions/0006-broad-phase.md).
#include "collision/broad_phase.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

namespace tumble {
namespace {

/// Every pair i < j whose boxes overlap and of which one is movable, in lexicographic order.
std::vector<ProxyPair> allOverlappingPairs(const std::vector<BroadPhaseProxy>& proxies)
{
    std::vector<ProxyPair> pairs;
    for (std::uint32_t i = 0; i < proxies.size(); ++i) {
        for (std::uint32_t j = i + 1; j < proxies.size(); ++j) {
            if ((proxies[i].movable || proxies[j].movable) &&
                overlaps(proxies[i].box, proxies[j].box)) {
                pairs.push_back(ProxyPair{i, j});
            }
        }
    }
    return pairs;
}

std::vector<ProxyPair> sweptPairs(BroadPhase& broadPhase,
                                  const std::vector<BroadPhaseProxy>& proxies)
{
    broadPhase.update(proxies);
    return std::vector<ProxyPair>(broadPhase.pairs().begin(), broadPhase.pairs().end());
}

/// `count` boxes in a region of side `side`, half sizes up to `largest`; one in `staticEvery`
/// static (0: none).
std::vector<BroadPhaseProxy> randomProxies(std::mt19937& random, std::size_t count, Real side,
                                           Real largest, std::size_t staticEvery)
{
    std::uniform_real_distribution<Real> coordinate(0.0, side);
    std::uniform_real_distribution<Real> halfSize(0.05, largest);
    std::vector<BroadPhaseProxy> proxies(count);
    for (std::size_t i = 0; i < count; ++i) {
        const Vec3 centre(coordinate(random), coordinate(random), 0.5 * coordinate(random));
        const Vec3 half(halfSize(random), halfSize(random), halfSize(random));
        proxies[i].box = Aabb{centre - half, centre + half};
        proxies[i].body = static_cast<std::uint32_t>(i);
        proxies[i].movable = staticEvery == 0 || i % staticEvery != 0;
    }
    return proxies;
}

void moveSlightly(std::mt19937& random, std::vector<BroadPhaseProxy>& proxies, Real distance)
{
    std::uniform_real_distribution<Real> step(-distance, distance);
    for (BroadPhaseProxy& proxy : proxies) {
        if (proxy.movable) {
            const Vec3 move(step(random), step(random), step(random));
            proxy.box.min += move;
            proxy.box.max += move;
        }
    }
}

TEST(BroadPhase, MatchesAllPairsOnRandomBoxes)
{
    std::mt19937 random(12345);
    for (const std::size_t count : {0, 1, 2, 10, 100, 700}) {
        for (const Real largest : {0.2, 1.0, 3.0}) {
            const auto proxies = randomProxies(random, count, 20.0, largest, 7);
            BroadPhase broadPhase;
            EXPECT_EQ(sweptPairs(broadPhase, proxies), allOverlappingPairs(proxies))
                << count << " boxes up to " << largest;
        }
    }
}

TEST(BroadPhase, ASweepSharedBetweenThreadsFindsEveryPairOnce)
{
    // 1500 boxes give two threads shares of 128 boxes; the pairs must be those of all pairs
    std::mt19937 random(777);
    for (const Real largest : {0.2, 1.0, 3.0}) {
        const auto proxies = randomProxies(random, 1500, 30.0, largest, 5);
        BroadPhase shared;
        shared.update(proxies, 2);
        const std::vector<ProxyPair> pairs(shared.pairs().begin(), shared.pairs().end());
        EXPECT_EQ(pairs, allOverlappingPairs(proxies)) << "boxes up to " << largest;
    }
}

TEST(BroadPhase, ASweepSharedBetweenThreadsGivesOneSortedList)
{
    // 1500 boxes make 10 shares on two threads, 9 on three and 8 on four; their pairs together
    // are put in proxy order, the same list whatever the shares, in buffers kept between sweeps
    std::mt19937 random(4242);
    const auto proxies = randomProxies(random, 1500, 30.0, 3.0, 5);
    const std::vector<ProxyPair> expected = allOverlappingPairs(proxies);
    // every box moved 1 along x and back, beyond its growth, so each update sweeps again
    auto moved = proxies;
    for (BroadPhaseProxy& proxy : moved) {
        proxy.box.min.x += 1.0;
        proxy.box.max.x += 1.0;
    }
    BroadPhase shared;
    shared.update(proxies, 2);
    const ProxyPair* buffer = shared.pairs().data();
    for (int update = 0; update < 3; ++update) {
        shared.update(moved, 2);
        ASSERT_TRUE(shared.sweptLastUpdate());
        shared.update(proxies, 2);
        ASSERT_TRUE(shared.sweptLastUpdate());
        const std::vector<ProxyPair> pairs(shared.pairs().begin(), shared.pairs().end());
        EXPECT_EQ(pairs, expected) << update;
        EXPECT_EQ(shared.pairs().data(), buffer) << update;
    }
    for (const int threads : {3, 4}) {
        BroadPhase more;
        more.update(proxies, threads);
        const std::vector<ProxyPair> pairs(more.pairs().begin(), more.pairs().end());
        EXPECT_EQ(pairs, expected) << threads << " threads";
    }
}

TEST(BroadPhase, StaticBoxesPairOnlyWithMovableOnes)
{
    std::vector<BroadPhaseProxy> proxies(3);
    proxies[0] = {Aabb{Vec3(0), Vec3(2)}, 0, false};
    proxies[1] = {Aabb{Vec3(1), Vec3(3)}, 1, false};
    proxies[2] = {Aabb{Vec3(1.5), Vec3(2.5)}, 2, true};
    BroadPhase broadPhase;
    EXPECT_EQ(sweptPairs(broadPhase, proxies),
              (std::vector<ProxyPair>{ProxyPair{0, 2}, ProxyPair{1, 2}}));
}

TEST(BroadPhase, BoxesSharingAFaceOverlap)
{
    // a row of unit cubes along x, each touching the next on a face; the sweep axis is x
    std::vector<BroadPhaseProxy> proxies;
    for (std::uint32_t i = 0; i < 5; ++i) {
        const Vec3 low(static_cast<Real>(i), 0, 0);
        proxies.push_back({Aabb{low, low + Vec3(1)}, i, true});
    }
    BroadPhase broadPhase;
    const std::vector<ProxyPair> expected{{0, 1}, {1, 2}, {2, 3}, {3, 4}};
    EXPECT_EQ(sweptPairs(broadPhase, proxies), expected);
    EXPECT_EQ(broadPhase.sweepAxis(), 0);
}

TEST(BroadPhase, SweepsAlongTheAxisOfLargestSpread)
{
    std::vector<BroadPhaseProxy> proxies;
    for (std::uint32_t i = 0; i < 10; ++i) {
        const Vec3 low(0.1 * (i % 3), 0.2 * (i % 2), 3.0 * i);
        proxies.push_back({Aabb{low, low + Vec3(1)}, i, true});
    }
    BroadPhase broadPhase;
    broadPhase.update(proxies);
    EXPECT_EQ(broadPhase.sweepAxis(), 2);
}

TEST(BroadPhase, IncrementalUpdatesAfterSmallMovesMatchAllPairs)
{
    std::mt19937 random(99);
    auto proxies = randomProxies(random, 500, 15.0, 0.8, 10);
    BroadPhase broadPhase;
    for (int step = 0; step < 60; ++step) {
        ASSERT_EQ(sweptPairs(broadPhase, proxies), allOverlappingPairs(proxies)) << step;
        moveSlightly(random, proxies, 0.05);
    }
}

TEST(BroadPhase, BoxPassingARowMatchesAllPairs)
{
    // one box walks along a row of unit cubes spaced 1.5 apart, passing one cube every few
    // calls: the insertion sort moves it one place at a time
    std::vector<BroadPhaseProxy> proxies;
    for (std::uint32_t i = 0; i < 40; ++i) {
        const Vec3 low(1.5 * i, 0.1 * (i % 3), 0);
        proxies.push_back({Aabb{low, low + Vec3(1)}, i, i % 4 != 0});
    }
    proxies[0].movable = true;
    BroadPhase broadPhase;
    for (int step = 0; step < 150; ++step) {
        ASSERT_EQ(sweptPairs(broadPhase, proxies), allOverlappingPairs(proxies)) << step;
        proxies[0].box.min.x += 0.4;
        proxies[0].box.max.x += 0.4;
    }
}

TEST(BroadPhase, TeleportsAndChangesOfCountMatchAllPairs)
{
    // large moves exceed the insertion sort's budget; a new count starts a new order
    std::mt19937 random(5);
    BroadPhase broadPhase;
    for (const std::size_t count : {300, 300, 280, 280, 320, 1, 0, 50}) {
        const auto proxies = randomProxies(random, count, 12.0, 1.0, 5);
        ASSERT_EQ(sweptPairs(broadPhase, proxies), allOverlappingPairs(proxies)) << count;
        auto moved = proxies;
        moveSlightly(random, moved, 6.0);
        ASSERT_EQ(sweptPairs(broadPhase, moved), allOverlappingPairs(moved)) << count;
    }
}

TEST(BroadPhase, OutputDependsOnlyOnTheInput)
{
    // the same boxes after a different history give the same pairs, in the same order
    std::mt19937 random(31);
    const auto proxies = randomProxies(random, 400, 15.0, 1.0, 9);
    BroadPhase fresh;
    const std::vector<ProxyPair> expected = sweptPairs(fresh, proxies);
    BroadPhase used;
    auto other = proxies;
    for (int step = 0; step < 5; ++step) {
        moveSlightly(random, other, 0.5);
        used.update(other);
    }
    EXPECT_EQ(sweptPairs(used, proxies), expected);
}

TEST(BroadPhase, ShuffledInputGivesTheSamePairsUpToRelabelling)
{
    std::mt19937 random(2024);
    const auto proxies = randomProxies(random, 600, 18.0, 1.0, 6);
    BroadPhase broadPhase;
    const std::vector<ProxyPair> expected = sweptPairs(broadPhase, proxies);
    for (int shuffle = 0; shuffle < 5; ++shuffle) {
        // proxy i moves to place slot[i]
        std::vector<std::uint32_t> slot(proxies.size());
        std::iota(slot.begin(), slot.end(), 0u);
        std::shuffle(slot.begin(), slot.end(), random);
        std::vector<BroadPhaseProxy> shuffled(proxies.size());
        std::vector<std::uint32_t> original(proxies.size());
        for (std::uint32_t i = 0; i < proxies.size(); ++i) {
            shuffled[slot[i]] = proxies[i];
            original[slot[i]] = i;
        }
        std::vector<ProxyPair> relabelled;
        for (const ProxyPair& pair : sweptPairs(broadPhase, shuffled)) {
            const std::uint32_t a = original[pair.a];
            const std::uint32_t b = original[pair.b];
            relabelled.push_back(ProxyPair{std::min(a, b), std::max(a, b)});
        }
        std::sort(relabelled.begin(), relabelled.end());
        EXPECT_EQ(relabelled, expected) << shuffle;
    }
}

TEST(BroadPhase, PairsAreSortedAndDistinct)
{
    std::mt19937 random(77);
    const auto proxies = randomProxies(random, 800, 10.0, 1.5, 0);
    BroadPhase broadPhase;
    broadPhase.update(proxies);
    const auto pairs = broadPhase.pairs();
    ASSERT_FALSE(pairs.empty());
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        EXPECT_LT(pairs[i].a, pairs[i].b);
        if (i > 0) {
            EXPECT_LT(pairs[i - 1], pairs[i]);
        }
    }
}

/// A row of `count` unit cubes along x, cube i at x = i + i * gap: touching for gap 0.
std::vector<BroadPhaseProxy> rowOfCubes(std::uint32_t count, Real gap)
{
    std::vector<BroadPhaseProxy> proxies;
    for (std::uint32_t i = 0; i < count; ++i) {
        const Vec3 low(static_cast<Real>(i) * (1.0 + gap), 0, 0);
        proxies.push_back({Aabb{low, low + Vec3(1)}, i, true});
    }
    return proxies;
}

TEST(BroadPhase, BoxesMovingWithinTheirGrowthKeepTheSweptPairsTestedAgain)
{
    // (10.3a): gaps of 1 um open between touching cubes, far inside the growth of 1/64 m, so the
    // update keeps the grown boxes' pairs; they no longer overlap and must be dropped, then come
    // back when the gaps close
    BroadPhase broadPhase;
    const std::vector<ProxyPair> touching{{0, 1}, {1, 2}, {2, 3}, {3, 4}};
    EXPECT_EQ(sweptPairs(broadPhase, rowOfCubes(5, 0.0)), touching);
    EXPECT_TRUE(broadPhase.sweptLastUpdate());
    EXPECT_EQ(sweptPairs(broadPhase, rowOfCubes(5, 1e-6)), std::vector<ProxyPair>{});
    EXPECT_FALSE(broadPhase.sweptLastUpdate());
    EXPECT_EQ(sweptPairs(broadPhase, rowOfCubes(5, 0.0)), touching);
    EXPECT_FALSE(broadPhase.sweptLastUpdate());
    // a cube moved 0.9 along the row leaves its grown box and its first neighbour
    auto moved = rowOfCubes(5, 0.0);
    moved[1].box.min.x += 0.9;
    moved[1].box.max.x += 0.9;
    EXPECT_EQ(sweptPairs(broadPhase, moved), allOverlappingPairs(moved));
    EXPECT_TRUE(broadPhase.sweptLastUpdate());
    EXPECT_EQ(allOverlappingPairs(moved), (std::vector<ProxyPair>{{1, 2}, {2, 3}, {3, 4}}));
}

TEST(BroadPhase, AProxyThatBecomesMovableIsSweptAgain)
{
    // two static boxes make no pair; the same boxes with one made movable do
    std::vector<BroadPhaseProxy> proxies(2);
    proxies[0] = {Aabb{Vec3(0), Vec3(2)}, 0, false};
    proxies[1] = {Aabb{Vec3(1), Vec3(3)}, 1, false};
    BroadPhase broadPhase;
    EXPECT_EQ(sweptPairs(broadPhase, proxies), std::vector<ProxyPair>{});
    proxies[1].movable = true;
    EXPECT_EQ(sweptPairs(broadPhase, proxies), (std::vector<ProxyPair>{{0, 1}}));
    EXPECT_TRUE(broadPhase.sweptLastUpdate());
}

TEST(BroadPhase, CreepingBoxesMatchAllPairsWhetherSweptOrNot)
{
    // moves of up to 0.4 mm a call: the smallest boxes (0.1 m) leave their growth (1.6 mm) after
    // some calls, the others keep it; every call must give all the overlapping pairs
    std::mt19937 random(8);
    auto proxies = randomProxies(random, 500, 15.0, 0.8, 10);
    BroadPhase broadPhase;
    int kept = 0;
    for (int step = 0; step < 80; ++step) {
        ASSERT_EQ(sweptPairs(broadPhase, proxies), allOverlappingPairs(proxies)) << step;
        kept += broadPhase.sweptLastUpdate() ? 0 : 1;
        moveSlightly(random, proxies, 4e-4);
    }
    EXPECT_GT(kept, 0);
    EXPECT_LT(kept, 79);
}

TEST(BroadPhase, SteadyUpdatesReuseTheirBuffers)
{
    std::mt19937 random(3);
    auto proxies = randomProxies(random, 300, 10.0, 0.5, 0);
    BroadPhase broadPhase;
    broadPhase.update(proxies);
    broadPhase.update(proxies);
    const ProxyPair* buffer = broadPhase.pairs().data();
    for (int step = 0; step < 10; ++step) {
        broadPhase.update(proxies);
        EXPECT_EQ(broadPhase.pairs().data(), buffer);
    }
}

} // namespace
} // namespace tumble
