// Greedy colouring: no colour moves a dynamic body twice; chains, stars, overflow
// (docs/physics/10-broad-phase.md, (10.5)).
#include "dynamics/constraint_colouring.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <vector>

namespace tumble {
namespace {

/// Checks that every constraint appears once and no colour holds two constraints sharing a
/// dynamic body.
::testing::AssertionResult isProperColouring(const ConstraintColours& colours,
                                             const std::vector<ProxyPair>& constraints,
                                             const std::vector<std::uint8_t>& isStatic)
{
    if (colours.offsets.size() != colours.colourCount + 2 ||
        colours.offsets.back() != constraints.size()) {
        return ::testing::AssertionFailure() << "offsets do not cover the constraints";
    }
    std::multiset<std::uint32_t> seen(colours.constraints.begin(), colours.constraints.end());
    for (std::uint32_t i = 0; i < constraints.size(); ++i) {
        if (seen.count(i) != 1) {
            return ::testing::AssertionFailure() << "constraint " << i << " not exactly once";
        }
    }
    for (std::uint32_t c = 0; c < colours.colourCount; ++c) {
        std::set<std::uint32_t> moved;
        for (const std::uint32_t index : colours.colour(c)) {
            for (const std::uint32_t body : {constraints[index].a, constraints[index].b}) {
                if (!isStatic[body] && !moved.insert(body).second) {
                    return ::testing::AssertionFailure()
                           << "colour " << c << " moves body " << body << " twice";
                }
            }
        }
    }
    return ::testing::AssertionSuccess();
}

std::vector<ProxyPair> star(std::uint32_t arms)
{
    std::vector<ProxyPair> constraints;
    for (std::uint32_t arm = 1; arm <= arms; ++arm) {
        constraints.push_back(ProxyPair{0, arm});
    }
    return constraints;
}

TEST(ConstraintColouring, RandomGraphsNeverMoveABodyTwiceInOneColour)
{
    std::mt19937 random(17);
    for (int trial = 0; trial < 40; ++trial) {
        const std::uint32_t bodyCount = 2 + random() % 150;
        std::vector<std::uint8_t> isStatic(bodyCount);
        for (auto& flag : isStatic) {
            flag = random() % 10 == 0;
        }
        std::vector<ProxyPair> constraints(random() % (3 * bodyCount));
        for (auto& constraint : constraints) {
            const std::uint32_t a = random() % bodyCount;
            const std::uint32_t b = (a + 1 + random() % (bodyCount - 1)) % bodyCount;
            constraint = ProxyPair{std::min(a, b), std::max(a, b)};
        }
        const std::uint32_t maxColours = trial % 2 ? 64 : 4;
        const ConstraintColours colours = colourConstraints(constraints, isStatic, maxColours);
        ASSERT_TRUE(isProperColouring(colours, constraints, isStatic)) << trial;
        EXPECT_LE(colours.colourCount, maxColours);
    }
}

TEST(ConstraintColouring, StaticBodyIsSharedWithinAColour)
{
    // five boxes on one static floor (body 0): all five contacts in the first colour
    std::vector<std::uint8_t> isStatic{1, 0, 0, 0, 0, 0};
    const std::vector<ProxyPair> constraints = star(5);
    const ConstraintColours colours = colourConstraints(constraints, isStatic, 64);
    EXPECT_EQ(colours.colourCount, 1u);
    EXPECT_EQ(colours.constraints, (std::vector<std::uint32_t>{0, 1, 2, 3, 4}));
    EXPECT_TRUE(colours.overflow().empty());
}

TEST(ConstraintColouring, ChainNeedsTwoColours)
{
    const std::vector<std::uint8_t> isStatic(8, 0);
    std::vector<ProxyPair> constraints;
    for (std::uint32_t i = 0; i + 1 < 8; ++i) {
        constraints.push_back(ProxyPair{i, i + 1});
    }
    const ConstraintColours colours = colourConstraints(constraints, isStatic, 64);
    ASSERT_TRUE(isProperColouring(colours, constraints, isStatic));
    EXPECT_EQ(colours.colourCount, 2u);
    EXPECT_EQ(colours.constraints, (std::vector<std::uint32_t>{0, 2, 4, 6, 1, 3, 5}));
    EXPECT_EQ(colours.offsets, (std::vector<std::uint32_t>{0, 4, 7, 7}));
}

TEST(ConstraintColouring, StarOfKNeedsKColours)
{
    for (const std::uint32_t arms : {1u, 2u, 7u, 64u}) {
        const std::vector<std::uint8_t> isStatic(arms + 1, 0);
        const std::vector<ProxyPair> constraints = star(arms);
        const ConstraintColours colours = colourConstraints(constraints, isStatic, 64);
        ASSERT_TRUE(isProperColouring(colours, constraints, isStatic));
        EXPECT_EQ(colours.colourCount, arms);
        EXPECT_TRUE(colours.overflow().empty());
    }
}

TEST(ConstraintColouring, ConstraintsBeyondTheLastColourOverflow)
{
    // a star of 10 with 4 colours: arms 1-4 take colours 0-3, arms 5-10 overflow in order;
    // with 64 colours, a star of 70 leaves 6
    std::vector<std::uint8_t> isStatic(11, 0);
    std::vector<ProxyPair> constraints = star(10);
    ConstraintColours colours = colourConstraints(constraints, isStatic, 4);
    ASSERT_TRUE(isProperColouring(colours, constraints, isStatic));
    EXPECT_EQ(colours.colourCount, 4u);
    const auto overflow = colours.overflow();
    EXPECT_EQ(std::vector<std::uint32_t>(overflow.begin(), overflow.end()),
              (std::vector<std::uint32_t>{4, 5, 6, 7, 8, 9}));

    isStatic.assign(71, 0);
    constraints = star(70);
    colours = colourConstraints(constraints, isStatic, 64);
    ASSERT_TRUE(isProperColouring(colours, constraints, isStatic));
    EXPECT_EQ(colours.colourCount, 64u);
    EXPECT_EQ(colours.overflow().size(), 6u);
}

TEST(ConstraintColouring, EmptyInputHasNoColours)
{
    const ConstraintColours colours = colourConstraints({}, {}, 8);
    EXPECT_EQ(colours.colourCount, 0u);
    EXPECT_EQ(colours.offsets, (std::vector<std::uint32_t>{0, 0}));
    EXPECT_TRUE(colours.overflow().empty());
}

} // namespace
} // namespace tumble
