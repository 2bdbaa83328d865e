// Islands of awake dynamic bodies: chains, static floors, sleeping bodies, independence of the
// link order (docs/physics/10-broad-phase.md, (10.4)).
#include "dynamics/islands.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

namespace tumble {
namespace {

using Bodies = std::vector<std::uint32_t>;

std::vector<Bodies> islandList(const Islands& islands)
{
    std::vector<Bodies> list;
    for (std::size_t k = 0; k < islands.count(); ++k) {
        list.emplace_back(islands.island(k).begin(), islands.island(k).end());
    }
    return list;
}

/// Reference: the components of the awake dynamic bodies by repeated relabelling.
std::vector<Bodies> componentsByRelabelling(const std::vector<std::uint8_t>& isDynamicAwake,
                                            const std::vector<ProxyPair>& links)
{
    std::vector<std::uint32_t> label(isDynamicAwake.size());
    std::iota(label.begin(), label.end(), 0u);
    for (bool changed = true; changed;) {
        changed = false;
        for (const ProxyPair& link : links) {
            if (isDynamicAwake[link.a] && isDynamicAwake[link.b] &&
                label[link.a] != label[link.b]) {
                const std::uint32_t lowest = std::min(label[link.a], label[link.b]);
                label[link.a] = label[link.b] = lowest;
                changed = true;
            }
        }
    }
    // labels settle on the smallest body of each component, so the map lists them in order
    std::map<std::uint32_t, Bodies> components;
    for (std::uint32_t body = 0; body < isDynamicAwake.size(); ++body) {
        if (isDynamicAwake[body]) {
            components[label[body]].push_back(body);
        }
    }
    std::vector<Bodies> list;
    for (auto& [smallest, bodies] : components) {
        list.push_back(std::move(bodies));
    }
    return list;
}

TEST(Islands, ChainIsOneIsland)
{
    const std::vector<std::uint8_t> dynamic(4, 1);
    const std::vector<ProxyPair> links{{2, 3}, {0, 1}, {1, 2}};
    const Islands islands = buildIslands(4, dynamic, links);
    EXPECT_EQ(islandList(islands), (std::vector<Bodies>{{0, 1, 2, 3}}));
}

TEST(Islands, BodyWithoutLinksIsAnIslandAlone)
{
    const std::vector<std::uint8_t> dynamic(3, 1);
    const std::vector<ProxyPair> links{{0, 2}};
    const Islands islands = buildIslands(3, dynamic, links);
    EXPECT_EQ(islandList(islands), (std::vector<Bodies>{{0, 2}, {1}}));
    EXPECT_EQ(islands.islandOfBody, (std::vector<std::uint32_t>{0, 1, 0}));
}

TEST(Islands, TwoStacksOnOneStaticFloorAreTwoIslands)
{
    // body 3 is the floor; stack {0, 1, 2} and stack {4, 5} both stand on it
    std::vector<std::uint8_t> dynamic(6, 1);
    dynamic[3] = 0;
    const std::vector<ProxyPair> links{{0, 3}, {0, 1}, {1, 2}, {3, 4}, {4, 5}};
    const Islands islands = buildIslands(6, dynamic, links);
    EXPECT_EQ(islandList(islands), (std::vector<Bodies>{{0, 1, 2}, {4, 5}}));
    EXPECT_EQ(islands.islandOfBody[3], kNoIsland);

    // each island's links include its contacts with the floor
    const IslandLinks islandLinks = linksOf(islands, links);
    ASSERT_EQ(islandLinks.offsets.size(), 3u);
    const auto first = islandLinks.island(0);
    const auto second = islandLinks.island(1);
    EXPECT_EQ(Bodies(first.begin(), first.end()), (Bodies{0, 1, 2}));
    EXPECT_EQ(Bodies(second.begin(), second.end()), (Bodies{3, 4}));
}

TEST(Islands, SleepingBodiesTakeNoPart)
{
    // body 1 asleep in the middle of a chain: the chain falls apart, and its links belong to
    // the awake ends
    const std::vector<std::uint8_t> awake{1, 0, 1};
    const std::vector<ProxyPair> links{{0, 1}, {1, 2}};
    const Islands islands = buildIslands(3, awake, links);
    EXPECT_EQ(islandList(islands), (std::vector<Bodies>{{0}, {2}}));
    const IslandLinks islandLinks = linksOf(islands, links);
    EXPECT_EQ(islandLinks.links, (Bodies{0, 1}));
    EXPECT_EQ(islandLinks.offsets, (Bodies{0, 1, 2}));
}

TEST(Islands, LinksBetweenStaticBodiesBelongToNoIsland)
{
    const std::vector<std::uint8_t> dynamic{0, 0, 1};
    const std::vector<ProxyPair> links{{0, 1}, {1, 2}};
    const Islands islands = buildIslands(3, dynamic, links);
    const IslandLinks islandLinks = linksOf(islands, links);
    EXPECT_EQ(islandLinks.links, (Bodies{1}));
}

TEST(Islands, OrderedByTheirSmallestBody)
{
    const std::vector<std::uint8_t> dynamic(6, 1);
    const std::vector<ProxyPair> links{{4, 5}, {1, 4}, {0, 3}};
    const Islands islands = buildIslands(6, dynamic, links);
    EXPECT_EQ(islandList(islands), (std::vector<Bodies>{{0, 3}, {1, 4, 5}, {2}}));
}

TEST(Islands, MatchConnectedComponentsOfRandomGraphs)
{
    std::mt19937 random(8);
    for (int trial = 0; trial < 50; ++trial) {
        const std::uint32_t bodyCount = 1 + random() % 200;
        std::vector<std::uint8_t> dynamic(bodyCount);
        for (auto& flag : dynamic) {
            flag = random() % 6 != 0;
        }
        std::vector<ProxyPair> links(random() % (bodyCount + 1));
        for (auto& link : links) {
            const std::uint32_t a = random() % bodyCount;
            const std::uint32_t b = random() % bodyCount;
            link = ProxyPair{std::min(a, b), std::max(a, b)};
        }
        const Islands islands = buildIslands(bodyCount, dynamic, links);
        ASSERT_EQ(islandList(islands), componentsByRelabelling(dynamic, links)) << trial;
    }
}

TEST(Islands, IndependentOfLinkOrderAndDirection)
{
    std::mt19937 random(44);
    const std::uint32_t bodyCount = 300;
    std::vector<std::uint8_t> dynamic(bodyCount);
    for (auto& flag : dynamic) {
        flag = random() % 8 != 0;
    }
    std::vector<ProxyPair> links(250);
    for (auto& link : links) {
        link = ProxyPair{static_cast<std::uint32_t>(random() % bodyCount),
                         static_cast<std::uint32_t>(random() % bodyCount)};
    }
    const Islands expected = buildIslands(bodyCount, dynamic, links);
    for (int shuffle = 0; shuffle < 5; ++shuffle) {
        std::shuffle(links.begin(), links.end(), random);
        for (auto& link : links) {
            if (random() % 2) {
                std::swap(link.a, link.b);
            }
        }
        const Islands islands = buildIslands(bodyCount, dynamic, links);
        EXPECT_EQ(islands.bodies, expected.bodies);
        EXPECT_EQ(islands.offsets, expected.offsets);
        EXPECT_EQ(islands.islandOfBody, expected.islandOfBody);
    }
}

} // namespace
} // namespace tumble
