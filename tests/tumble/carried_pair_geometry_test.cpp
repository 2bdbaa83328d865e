// A pair's geometry carried with its bodies (9.12): the relative move bounds how far B moved on
// A, a pair moved as one keeps its contact exactly, and within the reach the carried contact
// stays as close to a fresh search as docs/physics/09-box-box.md says.
#include "collision/carried_pair_geometry.hpp"

#include "collision/cuboid_features.hpp"
#include "collision/pair_geometry_cache.hpp"
#include "support/glm_printers.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble {
namespace {

/// carryPairGeometry into a fresh geometry.
CuboidPairGeometry carriedFrom(const CuboidPairGeometry& found, const Transform& keptA,
                               const Transform& keptB, const Transform& poseA,
                               const Transform& poseB, Real move)
{
    CuboidPairGeometry carried;
    carryPairGeometry(found, keptA, keptB, poseA, poseB, move, carried);
    return carried;
}

const Vec3 kUnit(1.0);
const Vec3 kHalf(0.5);
/// A unit cube on another, sunk 1e-5 into it, shifted so their faces overlap in a rectangle and
/// turned by 2e-3 rad about the vertical.
const Transform kBelow{Vec3(0.0), Quat(1.0, 0.0, 0.0, 0.0)};
const Transform kAbove{Vec3(0.5, 1.0 - 1e-5, 0.25), glm::normalize(Quat(1.0, 0.0, 1e-3, 0.0))};
constexpr Real kMargin = 1e-4;

Quat turn(const Vec3& axis, Real angle)
{
    const Vec3 unit = glm::normalize(axis);
    return {std::cos(0.5 * angle), std::sin(0.5 * angle) * unit};
}

/// `pose` moved by the rigid motion x -> rotation x + shift.
Transform moved(const Transform& pose, const Quat& rotation, const Vec3& shift)
{
    return {rotation * pose.position + shift, glm::normalize(rotation * pose.orientation)};
}

CuboidPairGeometry found(const Transform& a, const Transform& b)
{
    return findCuboidPairGeometry(cuboidFrame(a, kHalf), cuboidFrame(b, kHalf), kMargin);
}

/// The largest distance any corner of B moved in A's frame between the two pairs of poses.
Real largestCornerMove(const Transform& a0, const Transform& b0, const Transform& a1,
                       const Transform& b1)
{
    Real largest = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 local(corner & 1 ? 0.5 : -0.5, corner & 2 ? 0.5 : -0.5,
                         corner & 4 ? 0.5 : -0.5);
        const Vec3 then = glm::conjugate(a0.orientation) *
                          (b0.position + b0.orientation * local - a0.position);
        const Vec3 now = glm::conjugate(a1.orientation) *
                         (b1.position + b1.orientation * local - a1.position);
        largest = std::max(largest, glm::length(now - then));
    }
    return largest;
}

TEST(CarriedPairGeometry, APairMovedAsOneHasNotMovedRelativeToItself)
{
    const Quat rotation = turn(Vec3(1.0, 2.0, -0.5), 0.7);
    const Vec3 shift(3.0, -1.0, 2.5);
    const Transform a = moved(kBelow, rotation, shift);
    const Transform b = moved(kAbove, rotation, shift);
    const Real move = relativeMove(kBelow, kAbove, a, b, kHalf);
    EXPECT_LT(move, 1e-14);
    // carried, the contact is the one a fresh search finds at the moved poses
    const CuboidPairGeometry carried =
        carriedFrom(found(kBelow, kAbove), kBelow, kAbove, a, b, move);
    const PairManifold kept = manifoldWithin(carried, kMargin);
    const PairManifold fresh = manifoldWithin(found(a, b), kMargin);
    ASSERT_EQ(fresh.pointCount, 4);
    ASSERT_EQ(kept.pointCount, fresh.pointCount);
    EXPECT_LE(testing::maxDifference(kept.normal, fresh.normal), 1e-14);
    for (int i = 0; i < fresh.pointCount; ++i) {
        EXPECT_EQ(kept.points[i].id, fresh.points[i].id);
        EXPECT_LE(testing::maxDifference(kept.points[i].position, fresh.points[i].position),
                  1e-13);
        EXPECT_NEAR(kept.points[i].separation, fresh.points[i].separation, 1e-13);
    }
}

TEST(CarriedPairGeometry, RelativeMoveBoundsHowFarEveryCornerOfBMoved)
{
    // A and B both moved, B further: the bound |dc| + theta |h_B| is at least every corner's
    // move in A's frame, and for B turned about its own centre, about an axis square to a corner, it is reached
    // within 1 %
    const Transform a = moved(kBelow, turn(Vec3(0.0, 0.0, 1.0), 0.2), Vec3(0.1, 0.0, 0.0));
    const Transform b = moved(kAbove, turn(Vec3(0.0, 0.0, 1.0), 0.2), Vec3(0.1, 0.0, 0.0));
    const Transform bMoved{b.position + Vec3(0.0, 0.0, 3e-5),
                           glm::normalize(turn(Vec3(1.0, 0.0, 1.0), 2e-5) * b.orientation)};
    const Real move = relativeMove(kBelow, kAbove, a, bMoved, kHalf);
    EXPECT_GE(move, largestCornerMove(kBelow, kAbove, a, bMoved));
    const Transform bTurned{kAbove.position,
                            glm::normalize(turn(Vec3(1.0, -1.0, 0.0), 1e-4) * kAbove.orientation)};
    const Real turnMove = relativeMove(kBelow, kAbove, kBelow, bTurned, kHalf);
    EXPECT_NEAR(turnMove, 1e-4 * std::sqrt(0.75), 1e-12);
    EXPECT_GE(turnMove, largestCornerMove(kBelow, kAbove, kBelow, bTurned));
    EXPECT_GT(largestCornerMove(kBelow, kAbove, kBelow, bTurned), 0.99 * turnMove);
}

TEST(CarriedPairGeometry, WithinTheReachTheContactStaysWithinTheMoveOfAFreshOne)
{
    // B slides on A and tilts about a horizontal axis, d just under the reach (9.12)
    const Real reach = carryReach(kHalf, kHalf);
    EXPECT_DOUBLE_EQ(reach, kCarryShare * 0.5);
    const Transform b{kAbove.position + Vec3(0.5 * reach, -0.1 * reach, 0.2 * reach),
                      glm::normalize(turn(Vec3(1.0, 0.0, 0.3), 0.3 * reach) *
                                     kAbove.orientation)};
    const Real move = relativeMove(kBelow, kAbove, kBelow, b, kHalf);
    ASSERT_LE(move, reach);
    const CuboidPairGeometry carried =
        carriedFrom(found(kBelow, kAbove), kBelow, kAbove, kBelow, b, move);
    const PairManifold kept = manifoldWithin(carried, kMargin);
    const PairManifold fresh = manifoldWithin(found(kBelow, b), kMargin);
    ASSERT_EQ(kept.pointCount, fresh.pointCount);
    for (int i = 0; i < fresh.pointCount; ++i) {
        EXPECT_EQ(kept.points[i].id, fresh.points[i].id);
        EXPECT_LE(glm::length(kept.points[i].position - fresh.points[i].position), move);
        // the incident face tilts by under 1e-5 rad over the reference face: a point moved
        // along it by at most d changes its separation by at most d times that slope
        EXPECT_NEAR(kept.points[i].separation, fresh.points[i].separation, 1e-5 * move + 1e-15);
    }
    EXPECT_LE(carried.largestSeparation, found(kBelow, b).largestSeparation);
}

TEST(CarriedPairGeometry, APairCarriedAsApartStaysApart)
{
    // apart by 0.01 and searched with a margin of 1e-4: the search stopped at an axis beyond it
    const Transform apart{kAbove.position + Vec3(0.0, 0.01, 0.0), kAbove.orientation};
    const CuboidPairGeometry stopped = found(kBelow, apart);
    ASSERT_FALSE(stopped.complete);
    const Transform closer{apart.position - Vec3(0.0, 4e-5, 0.0), apart.orientation};
    const Real move = relativeMove(kBelow, apart, kBelow, closer, kHalf);
    const CuboidPairGeometry carried =
        carriedFrom(stopped, kBelow, apart, kBelow, closer, move);
    EXPECT_DOUBLE_EQ(carried.largestSeparation, stopped.largestSeparation - move);
    EXPECT_LE(carried.largestSeparation, found(kBelow, closer).largestSeparation);
    EXPECT_TRUE(decidesMargin(carried, kMargin));
    EXPECT_EQ(manifoldWithin(carried, kMargin).pointCount, 0);
}

TEST(CarriedPairGeometry, TheCacheCarriesOnlyWhenAskedAndWithinTheReach)
{
    PairGeometryCache cache;
    CuboidPairGeometry scratch;
    cache.geometry(7, kBelow, kHalf, kAbove, kHalf, kMargin, &scratch);
    const Real reach = carryReach(kHalf, kHalf);
    const Transform near{kAbove.position + Vec3(0.5 * reach, 0.0, 0.0), kAbove.orientation};
    const PairManifold fresh = manifoldWithin(found(kBelow, near), kMargin);
    // not asked to carry: found again, the same bits as a fresh search
    const PairManifold again =
        manifoldWithin(cache.geometry(7, kBelow, kHalf, near, kHalf, kMargin), kMargin);
    ASSERT_EQ(again.pointCount, fresh.pointCount);
    for (int i = 0; i < fresh.pointCount; ++i) {
        EXPECT_EQ(again.points[i].position, fresh.points[i].position);
    }
    // asked to carry from there: half a reach on is carried, one and a half is found again
    const Transform nearer{near.position + Vec3(0.5 * reach, 0.0, 0.0), near.orientation};
    const CuboidPairGeometry& carried =
        cache.geometry(7, kBelow, kHalf, nearer, kHalf, kMargin, &scratch);
    const CuboidPairGeometry expected = carriedFrom(
        found(kBelow, near), kBelow, near, kBelow, nearer, 0.5 * reach);
    // written where the caller asked, not kept in the cache
    EXPECT_EQ(&carried, &scratch);
    EXPECT_EQ(carried.points.points[0].position, expected.points.points[0].position);
    const Transform far{near.position + Vec3(1.5 * reach, 0.0, 0.0), near.orientation};
    const CuboidPairGeometry& refound =
        cache.geometry(7, kBelow, kHalf, far, kHalf, kMargin, &scratch);
    EXPECT_NE(&refound, &scratch);
    const PairManifold farther = manifoldWithin(refound, kMargin);
    const PairManifold farFresh = manifoldWithin(found(kBelow, far), kMargin);
    ASSERT_EQ(farther.pointCount, farFresh.pointCount);
    for (int i = 0; i < farFresh.pointCount; ++i) {
        EXPECT_EQ(farther.points[i].position, farFresh.points[i].position);
        EXPECT_EQ(farther.points[i].separation, farFresh.points[i].separation);
    }
}

} // namespace
} // namespace tumble
