// The narrow phase's memory of a body's pairs: kept geometry is used only within the bounds of
// (9.11), and stays that close to a fresh one (docs/physics/09-box-box.md).
#include "collision/pair_geometry_cache.hpp"

#include "step/island_contacts.hpp"
#include "support/glm_printers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

namespace tumble {
namespace {

const Quat kIdentity(1.0, 0.0, 0.0, 0.0);
const Vec3 kUnit(1.0);
/// A unit cube on another, sunk 1e-5 into it and shifted so their faces overlap in a rectangle.
const Transform kBelow{Vec3(0.0), kIdentity};
const Transform kAbove{Vec3(0.5, 2.0 - 1e-5, 0.25), glm::normalize(Quat(1.0, 0.0, 1e-3, 0.0))};
constexpr Real kMargin = 1e-4;
/// (9.11) bounds each point's move by kPairCacheDistance + kPairCacheAngle r for r up to the half
/// diagonal sqrt(3) of each cube; a separation or a position changes by at most the sum for both
/// bodies, plus rounding.
const Real kReuseError = 2.0 * (kPairCacheDistance + std::sqrt(3.0) * kPairCacheAngle) + 1e-12;

Transform moved(const Transform& pose, Real distance, Real angle)
{
    const Vec3 axis = glm::normalize(Vec3(1.0, 2.0, -1.0));
    return {pose.position + distance * axis,
            glm::normalize(Quat(std::cos(0.5 * angle), std::sin(0.5 * angle) * axis) *
                           pose.orientation)};
}

PairManifold freshManifold(const Transform& a, const Transform& b)
{
    return collideCuboids(a, kUnit, b, kUnit, kMargin);
}

TEST(PairGeometryCache, PoseWithinTheBoundsIsWithinReachAndOneBeyondIsNot)
{
    EXPECT_TRUE(withinPairCacheReach(moved(kAbove, 0.9 * kPairCacheDistance, 0.0), kAbove));
    EXPECT_TRUE(withinPairCacheReach(moved(kAbove, 0.0, 0.9 * kPairCacheAngle), kAbove));
    EXPECT_FALSE(withinPairCacheReach(moved(kAbove, 1.1 * kPairCacheDistance, 0.0), kAbove));
    EXPECT_FALSE(withinPairCacheReach(moved(kAbove, 0.0, 1.1 * kPairCacheAngle), kAbove));
    // -q is the same orientation, but counts as apart: the cache only finds it again
    const Transform flipped{kAbove.position, -kAbove.orientation};
    EXPECT_FALSE(withinPairCacheReach(flipped, kAbove));
}

TEST(PairGeometryCache, KeptGeometryWithinReachMatchesAFreshOne)
{
    PairGeometryCache cache;
    const PairManifold kept = manifoldWithin(
        cache.geometry(7, kBelow, kUnit, kAbove, kUnit, kMargin), kMargin);
    ASSERT_EQ(kept.pointCount, 4);
    // both bodies moved and turned by just under the bounds: the kept geometry is returned
    const Transform below = moved(kBelow, 0.9 * kPairCacheDistance, 0.9 * kPairCacheAngle);
    const Transform above = moved(kAbove, -0.9 * kPairCacheDistance, -0.9 * kPairCacheAngle);
    const PairManifold reused =
        manifoldWithin(cache.geometry(7, below, kUnit, above, kUnit, kMargin), kMargin);
    const PairManifold fresh = freshManifold(below, above);
    ASSERT_EQ(reused.pointCount, fresh.pointCount);
    EXPECT_EQ(reused.normal, kept.normal);
    for (int i = 0; i < fresh.pointCount; ++i) {
        EXPECT_EQ(reused.points[i].position, kept.points[i].position);
        EXPECT_EQ(reused.points[i].id, fresh.points[i].id);
        EXPECT_LE(testing::maxDifference(reused.points[i].position, fresh.points[i].position),
                  kReuseError);
        EXPECT_NEAR(reused.points[i].separation, fresh.points[i].separation, kReuseError);
    }
    EXPECT_LE(testing::maxDifference(reused.normal, fresh.normal), 2.0 * kPairCacheAngle);
}

TEST(PairGeometryCache, PairThatMovedBeyondTheBoundsIsFoundAgain)
{
    for (const auto& [distance, angle] :
         {std::pair{1.1 * kPairCacheDistance, 0.0}, std::pair{0.0, 1.1 * kPairCacheAngle}}) {
        PairGeometryCache cache;
        cache.geometry(7, kBelow, kUnit, kAbove, kUnit, kMargin);
        const Transform above = moved(kAbove, distance, angle);
        const PairManifold again =
            manifoldWithin(cache.geometry(7, kBelow, kUnit, above, kUnit, kMargin), kMargin);
        const PairManifold fresh = freshManifold(kBelow, above);
        ASSERT_EQ(again.pointCount, fresh.pointCount);
        for (int i = 0; i < fresh.pointCount; ++i) {
            EXPECT_EQ(again.points[i].position, fresh.points[i].position);
            EXPECT_EQ(again.points[i].separation, fresh.points[i].separation);
        }
    }
}

TEST(PairGeometryCache, NewSizeOrUndecidedMarginIsFoundAgain)
{
    PairGeometryCache cache;
    // apart by 0.01: a search with margin 1e-4 stops at the first axis beyond it
    const Transform apart{kAbove.position + Vec3(0.0, 0.01 + 1e-5, 0.0), kIdentity};
    EXPECT_FALSE(cache.geometry(7, kBelow, kUnit, apart, kUnit, kMargin).complete);
    // a wider margin is not decided by that bound: searched again, with points
    const CuboidPairGeometry& wide = cache.geometry(7, kBelow, kUnit, apart, kUnit, 0.02);
    EXPECT_TRUE(wide.complete);
    EXPECT_EQ(manifoldWithin(wide, 0.02).pointCount, 4);
    // the same poses with B half a metre taller: found again, 0.49 deep
    const CuboidPairGeometry& taller =
        cache.geometry(7, kBelow, kUnit, apart, Vec3(1.0, 1.5, 1.0), 0.02);
    EXPECT_NEAR(taller.largestSeparation, -0.49, 1e-12);
}

TEST(PairGeometryCache, PairsNotAskedForAreForgotten)
{
    PairGeometryCache cache;
    cache.geometry(3, kBelow, kUnit, kAbove, kUnit, kMargin);
    cache.geometry(7, kBelow, kUnit, kAbove, kUnit, kMargin);
    cache.forgetUnasked();
    EXPECT_EQ(cache.size(), 2u);
    cache.geometry(7, kBelow, kUnit, kAbove, kUnit, kMargin);
    cache.forgetUnasked();
    EXPECT_EQ(cache.size(), 1u);
}

TEST(PairGeometryCache, ARestingPairsAnswerHoldsOnlyAtItsPosesSizesAndMarginUntilAskedAgain)
{
    // (10.4b)
    PairGeometryCache cache;
    const auto answer = [&] {
        return cache.restingTouch(7, kBelow, kUnit, kAbove, kUnit, kMargin);
    };
    EXPECT_FALSE(answer()) << "no entry yet";
    cache.geometry(7, kBelow, kUnit, kAbove, kUnit, kMargin);
    EXPECT_FALSE(answer()) << "nothing remembered";
    cache.rememberRestingTouch(7, kBelow, kAbove, kMargin, true);
    EXPECT_EQ(answer(), std::optional<bool>(true));
    cache.rememberRestingTouch(7, kBelow, kAbove, kMargin, false);
    EXPECT_EQ(answer(), std::optional<bool>(false));
    // any other pose, even within (9.11)'s reach, another size or another margin: not known
    EXPECT_FALSE(cache.restingTouch(7, moved(kBelow, 1e-12, 0.0), kUnit, kAbove, kUnit, kMargin));
    EXPECT_FALSE(cache.restingTouch(7, kBelow, kUnit, moved(kAbove, 0.0, 1e-12), kUnit, kMargin));
    EXPECT_FALSE(cache.restingTouch(7, kBelow, kUnit, kAbove, kUnit, 2.0 * kMargin));
    EXPECT_FALSE(cache.restingTouch(7, kBelow, 0.5 * kUnit, kAbove, kUnit, kMargin));
    EXPECT_FALSE(cache.restingTouch(7, kBelow, kUnit, kAbove, 2.0 * kUnit, kMargin));
    // asking only for the answer keeps the pair; asking for the geometry forgets the answer
    cache.forgetUnasked();
    EXPECT_EQ(answer(), std::optional<bool>(false));
    cache.forgetUnasked();
    EXPECT_EQ(cache.size(), 1u);
    cache.geometry(7, kBelow, kUnit, kAbove, kUnit, kMargin);
    EXPECT_FALSE(answer());
}

TEST(PairGeometryCache, ARestingPairTestedAgainGivesTheAnswerMayTouchGives)
{
    // slot 0 a static box, slot 1 a box of the same size resting on it; then lifted 0.5 m
    std::vector<BodySlot> slots(2);
    slots[0].body.motion = BodyMotion::Static;
    slots[1].body.position = Vec3(0.0, 2.0 - 1e-5, 0.0);
    EXPECT_TRUE(restingMayTouch(slots, 0, 1, kMargin, 0.0, 0.0, false));
    EXPECT_TRUE(restingMayTouch(slots, 0, 1, kMargin, 0.0, 0.0, false));
    slots[1].body.position.y += 0.5;
    EXPECT_FALSE(restingMayTouch(slots, 0, 1, kMargin, 0.0, 0.0, false));
    EXPECT_FALSE(mayTouch(slots, 0, 1, kMargin, 0.0, 0.0, false));
    EXPECT_TRUE(restingMayTouch(slots, 0, 1, kMargin, 0.5, 0.0, false)) << "a larger reach";
}

TEST(PairGeometryCache, ABodyOnTwoStaticBoxesKeepsBothPairs)
{
    // slots 0 and 1: static boxes side by side; slot 2: a cube across both. The cube keeps
    // both pairs (9.11), each under its static box, so neither pushes the other out
    std::vector<BodySlot> slots(3);
    for (std::uint32_t k = 0; k < 2; ++k) {
        slots[k].body.motion = BodyMotion::Static;
        slots[k].body.position = Vec3(2.0 * k - 1.0, 0.0, 0.0);
    }
    slots[2].body.position = Vec3(0.0, 2.0 - 1e-5, 0.0);
    EXPECT_EQ(pairGeometryOwner(slots, 0, 2), 2u);
    EXPECT_EQ(pairGeometryOwner(slots, 1, 2), 2u);
    pairGeometry(slots, 0, 2, kMargin);
    pairGeometry(slots, 1, 2, kMargin);
    slots[2].pairGeometry.forgetUnasked();
    EXPECT_EQ(slots[2].pairGeometry.size(), 2u);
    // asked again in turn, each pair finds its own entry (the kept ones stay where they are)
    const CuboidPairGeometry* left = &pairGeometry(slots, 0, 2, kMargin);
    const CuboidPairGeometry* right = &pairGeometry(slots, 1, 2, kMargin);
    EXPECT_NE(left, right);
    EXPECT_EQ(&pairGeometry(slots, 0, 2, kMargin), left);
    EXPECT_EQ(&pairGeometry(slots, 1, 2, kMargin), right);
    EXPECT_EQ(slots[2].pairGeometry.size(), 2u);
    EXPECT_EQ(manifoldWithin(*left, kMargin).pointCount, 4);
    EXPECT_EQ(manifoldWithin(*right, kMargin).pointCount, 4);
    EXPECT_TRUE(slots[0].pairGeometry.size() == 0 && slots[1].pairGeometry.size() == 0)
        << "a static box keeps no pair";
}

} // namespace
} // namespace tumble
