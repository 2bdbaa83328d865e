// Boxes of a cuboid at a pose and over a step (docs/physics/10-broad-phase.md, (10.1)-(10.3)).
#include "collision/aabb.hpp"

#include "support/glm_printers.hpp"
#include "tumble/shape.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

namespace tumble {
namespace {

using testing::near;

/// Box corners computed from a rotation matrix and the vertices from a quaternion: a few roundings
/// of coordinates of order 10.
constexpr Real kCoordinates = 1e-12;

/// The exact pose at time s of a body moving ballistically and turning at the constant world
/// angular velocity w: q(s) = exp(w s / 2) q(0).
Transform exactPose(const Transform& start, const Vec3& velocity, const Vec3& gravity,
                    const Vec3& angularVelocity, Real s)
{
    const Real speed = glm::length(angularVelocity);
    const Quat turn = speed > 0.0 ? axisAngle(angularVelocity / speed, speed * s) : Quat(1, 0, 0, 0);
    return Transform{start.position + velocity * s + 0.5 * gravity * s * s,
                     glm::normalize(turn * start.orientation)};
}

bool contains(const Aabb& box, const Vec3& point, Real tolerance)
{
    return glm::all(glm::lessThanEqual(box.min - Vec3(tolerance), point)) &&
           glm::all(glm::lessThanEqual(point, box.max + Vec3(tolerance)));
}

Quat randomOrientation(std::mt19937& random)
{
    std::normal_distribution<Real> gaussian;
    return glm::normalize(Quat(gaussian(random), gaussian(random), gaussian(random),
                               gaussian(random)));
}

Vec3 randomVector(std::mt19937& random, Real scale)
{
    std::uniform_real_distribution<Real> uniform(-scale, scale);
    return Vec3(uniform(random), uniform(random), uniform(random));
}

TEST(Aabb, TouchingBoxesOverlap)
{
    const Aabb unit{Vec3(0), Vec3(1)};
    EXPECT_TRUE(overlaps(unit, Aabb{Vec3(1, 0, 0), Vec3(2, 1, 1)}));
    EXPECT_TRUE(overlaps(unit, Aabb{Vec3(1, 1, 1), Vec3(2, 2, 2)}));
    EXPECT_FALSE(overlaps(unit, Aabb{Vec3(1.0 + 1e-12, 0, 0), Vec3(2, 1, 1)}));
    EXPECT_FALSE(overlaps(unit, Aabb{Vec3(0, 0, -2), Vec3(1, 1, -1e-12)}));
}

TEST(Aabb, MergedExpandedAndSurfaceArea)
{
    const Aabb first{Vec3(0, 0, 0), Vec3(1, 2, 3)};
    const Aabb second{Vec3(-1, 1, 1), Vec3(0.5, 4, 2)};
    const Aabb both = merged(first, second);
    EXPECT_EQ(both.min, Vec3(-1, 0, 0));
    EXPECT_EQ(both.max, Vec3(1, 4, 3));
    const Aabb grown = expanded(first, 0.5);
    EXPECT_EQ(grown.min, Vec3(-0.5));
    EXPECT_EQ(grown.max, Vec3(1.5, 2.5, 3.5));
    EXPECT_DOUBLE_EQ(surfaceArea(first), 2.0 * (2.0 + 6.0 + 3.0));
}

TEST(Aabb, CubeTurnedFortyFiveDegreesAboutZ)
{
    const Transform pose{Vec3(1, 2, 3), axisAngle(Vec3(0, 0, 1), glm::radians(45.0))};
    const Aabb box = cuboidAabb(pose, Vec3(1));
    const Vec3 halfWidths(std::sqrt(2.0), std::sqrt(2.0), 1.0);
    EXPECT_TRUE(near(box.min, pose.position - halfWidths, kCoordinates));
    EXPECT_TRUE(near(box.max, pose.position + halfWidths, kCoordinates));
}

TEST(Aabb, RotatedCuboidBoxIsTheBoxOfItsVertices)
{
    std::mt19937 random(20240611);
    for (int trial = 0; trial < 200; ++trial) {
        const Transform pose{randomVector(random, 10.0), randomOrientation(random)};
        const Vec3 halfExtents = glm::abs(randomVector(random, 2.0)) + Vec3(0.1);
        Aabb vertices{Vec3(INFINITY), Vec3(-INFINITY)};
        for (const Vec3& local : cuboidVertices(halfExtents)) {
            const Vec3 world = pose.position + pose.orientation * local;
            vertices = merged(vertices, Aabb{world, world});
        }
        const Aabb box = cuboidAabb(pose, halfExtents);
        EXPECT_TRUE(near(box.min, vertices.min, kCoordinates));
        EXPECT_TRUE(near(box.max, vertices.max, kCoordinates));
    }
}

TEST(Aabb, SweptBoxContainsTheCuboidThroughoutTheStep)
{
    // random throws, slow to fast spins (turns past the bound's angle 2 included), short and
    // long steps; the vertices at 201 times of the exact motion, with no margin
    std::mt19937 random(7);
    std::uniform_real_distribution<Real> stepLength(1e-3, 0.5);
    const Vec3 gravity(0.0, -9.81, 0.0);
    for (int trial = 0; trial < 300; ++trial) {
        const Transform start{randomVector(random, 5.0), randomOrientation(random)};
        const Vec3 halfExtents = glm::abs(randomVector(random, 2.0)) + Vec3(0.05);
        const Vec3 velocity = randomVector(random, 10.0);
        const Vec3 angularVelocity = randomVector(random, trial % 3 == 0 ? 40.0 : 3.0);
        const Real dt = stepLength(random);
        const Vec3 trialGravity = trial % 5 == 0 ? randomVector(random, 20.0) : gravity;
        const Aabb box = sweptCuboidAabb(start, halfExtents, velocity, trialGravity,
                                         angularVelocity, dt, 0.0);
        for (int sample = 0; sample <= 200; ++sample) {
            const Real s = dt * sample / 200.0;
            const Transform pose = exactPose(start, velocity, trialGravity, angularVelocity, s);
            for (const Vec3& local : cuboidVertices(halfExtents)) {
                const Vec3 vertex = pose.position + pose.orientation * local;
                ASSERT_TRUE(contains(box, vertex, kCoordinates))
                    << "trial " << trial << " s " << s << " vertex "
                    << ::testing::PrintToString(vertex);
            }
        }
    }
}

TEST(Aabb, SweptBoxCoversTheApexOfAThrownBody)
{
    // thrown up at 5 m/s for a step of 1 s: the apex v^2/(2g) at s = v/g lies between the ends,
    // far above both of them (0 and 0.095 m)
    const Transform start{Vec3(0), Quat(1, 0, 0, 0)};
    const Vec3 halfExtents(0.5);
    const Real g = 9.81;
    const Aabb box = sweptCuboidAabb(start, halfExtents, Vec3(0, 5, 0), Vec3(0, -g, 0), Vec3(0),
                                     1.0, 0.0);
    const Real apex = 25.0 / (2.0 * g);
    EXPECT_NEAR(box.max.y, apex + 0.5, kCoordinates);
    EXPECT_NEAR(box.min.y, -0.5, kCoordinates);
    EXPECT_TRUE(near(box.min, Vec3(-0.5, -0.5, -0.5), kCoordinates));
}

TEST(Aabb, SweptBoxOfABodyAtRestIsItsBoxGrownByTheMargin)
{
    const Transform pose{Vec3(1, 2, 3), axisAngle(glm::normalize(Vec3(1, 2, 3)), 0.7)};
    const Vec3 halfExtents(0.5, 1.5, 0.25);
    const Aabb exact = expanded(cuboidAabb(pose, halfExtents), 0.01);
    const Aabb swept = sweptCuboidAabb(pose, halfExtents, Vec3(0), Vec3(0), Vec3(0), 0.1, 0.01);
    EXPECT_EQ(swept.min, exact.min);
    EXPECT_EQ(swept.max, exact.max);
}

TEST(Aabb, SweptBoxOfAFastSpinIsTheBallOfTheHalfDiagonal)
{
    // a turn of more than 2 rad: any orientation is possible, so the box is the half diagonal's
    // sphere's box about the centre, and no larger (10.3)
    const Transform pose{Vec3(0), axisAngle(Vec3(0, 1, 0), 0.3)};
    const Vec3 halfExtents(1, 2, 2);
    const Aabb box = sweptCuboidAabb(pose, halfExtents, Vec3(0), Vec3(0), Vec3(0, 0, 30), 0.1, 0.0);
    EXPECT_TRUE(near(box.min, Vec3(-3), kCoordinates));
    EXPECT_TRUE(near(box.max, Vec3(3), kCoordinates));
}

TEST(Aabb, SweptBoxOfASmallTurnGrowsByTheTurnTimesTheHalfDiagonal)
{
    const Vec3 halfExtents(1, 2, 2);
    const Aabb box =
        sweptCuboidAabb(Transform{}, halfExtents, Vec3(0), Vec3(0), Vec3(0.1, 0, 0), 0.1, 0.0);
    const Real reach = 0.01 * 3.0;
    EXPECT_TRUE(near(box.max, halfExtents + Vec3(reach), kCoordinates));
    EXPECT_TRUE(near(box.min, -halfExtents - Vec3(reach), kCoordinates));
}

} // namespace
} // namespace tumble
