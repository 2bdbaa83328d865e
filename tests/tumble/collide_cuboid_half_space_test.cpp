// A cuboid against a half-space of any orientation (docs/physics/04-detection.md, (4.1)): the
// vertices within the margin, deepest first, and none for a body beyond its half diagonal.
#include "collision/collide_cuboid_half_space.hpp"

#include "support/glm_printers.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble {
namespace {

constexpr Real kMargin = 0.01;
/// Heights after a rotation and a translation: a few roundings of order 1e-16.
constexpr Real kHeights = 1e-12;

/// A unit cube (half extents 1) turned so that its vertex (1, 1, 1) points straight down: that
/// vertex is the one nearest the ground, at the centre's height less the half diagonal sqrt(3),
/// so the test's early bound (centre less |h|) is met exactly.
Transform cornerDown(Real height)
{
    return {Vec3(0.5, height, -0.25), Quat(glm::normalize(Vec3(1, 1, 1)), Vec3(0, -1, 0))};
}

TEST(CollideCuboidHalfSpace, ACornerJustWithinTheMarginIsFound)
{
    const Real gap = kMargin - 1e-6;
    const PairManifold manifold = collideCuboidHalfSpace(
        cornerDown(std::sqrt(3.0) + gap), Vec3(1), Vec3(0), Vec3(0, 1, 0), kMargin);
    ASSERT_EQ(manifold.pointCount, 1);
    EXPECT_EQ(manifold.points[0].id, 7u) << "the vertex (1, 1, 1)";
    EXPECT_NEAR(manifold.points[0].separation, gap, kHeights);
    // midway between the vertex and the plane, straight below the centre
    EXPECT_NEAR(manifold.points[0].position.x, 0.5, kHeights);
    EXPECT_NEAR(manifold.points[0].position.y, 0.5 * gap, kHeights);
    EXPECT_NEAR(manifold.points[0].position.z, -0.25, kHeights);
}

TEST(CollideCuboidHalfSpace, ACornerJustBeyondTheMarginIsNot)
{
    const PairManifold manifold = collideCuboidHalfSpace(
        cornerDown(std::sqrt(3.0) + kMargin + 1e-6), Vec3(1), Vec3(0), Vec3(0, 1, 0), kMargin);
    EXPECT_EQ(manifold.pointCount, 0);
    EXPECT_EQ(manifold.normal, Vec3(0, 1, 0));
}

TEST(CollideCuboidHalfSpace, AnUprightBoxAboveTheBoundStillFindsItsFace)
{
    // upright, the lowest face is at the centre less h_y = 0.5, far nearer than less |h| = 1.5:
    // the bound passes it on to the vertices
    const Vec3 half(1.0, 0.5, 0.25);
    const PairManifold manifold = collideCuboidHalfSpace(
        Transform{Vec3(3, 0.5 + 0.004, 1), Quat(1, 0, 0, 0)}, half, Vec3(0), Vec3(0, 1, 0),
        kMargin);
    ASSERT_EQ(manifold.pointCount, 4);
    for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR(manifold.points[k].separation, 0.004, kHeights) << k;
    }
}

TEST(CollideCuboidHalfSpace, ATiltedPlaneTouchesAnEdge)
{
    // the plane x + y = 0 through the origin, its normal (1, 1, 0)/sqrt(2); an axis-aligned unit
    // cube's edge x = y = -1 lies at (c - 2)/sqrt(2) for a centre at x = y = c/2
    const Vec3 normal = glm::normalize(Vec3(1, 1, 0));
    const Real gap = 0.005;
    const Real c = 2.0 + gap * std::sqrt(2.0);
    const PairManifold manifold = collideCuboidHalfSpace(
        Transform{Vec3(0.5 * c, 0.5 * c, 7), Quat(1, 0, 0, 0)}, Vec3(1), Vec3(0), normal,
        kMargin);
    ASSERT_EQ(manifold.pointCount, 2);
    EXPECT_NEAR(manifold.points[0].separation, gap, kHeights);
    EXPECT_NEAR(manifold.points[1].separation, gap, kHeights);
    EXPECT_EQ(manifold.normal, normal);
    const PairManifold away = collideCuboidHalfSpace(
        Transform{Vec3(0.5 * c + 0.01, 0.5 * c + 0.01, 7), Quat(1, 0, 0, 0)}, Vec3(1), Vec3(0),
        normal, kMargin);
    EXPECT_EQ(away.pointCount, 0);
}

} // namespace
} // namespace tumble
