// Property tests over seeded random draws: for random cuboids, orientations and states the
// library's invariants hold (issue 6; docs/robustness.md).
#include "random_draws.hpp"

#include "support/glm_printers.hpp"

#include "tumble/impulse_target.hpp"
#include "tumble/world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace tumble::robustness {
namespace {

using tumble::testing::maxDifference;

/// Draws per property: seeds 0 .. kSeeds - 1, each its own test case so a failure names its seed.
constexpr int kSeeds = 200;

BodyDef randomBody(Draws& draws)
{
    BodyDef def;
    def.mass = draws.logUniform(1e-3, 1e4);
    def.shape.size = Vec3(draws.logUniform(0.01, 100.0), draws.logUniform(0.01, 100.0),
                          draws.logUniform(0.01, 100.0));
    def.orientation = draws.rotation();
    def.position = draws.vec3(-10.0, 10.0);
    def.linearVelocity = draws.vec3(-20.0, 20.0);
    def.angularVelocity = draws.vec3(-5.0, 5.0);
    def.material.restitution = draws.unit();
    def.material.friction = draws.uniform(0.0, 2.0);
    return def;
}

/// A random point inside the body, world coordinates.
Vec3 pointInside(Draws& draws, const Body& body)
{
    const Vec3 half = body.shape.halfExtents();
    return body.worldPoint(Vec3(draws.uniform(-half.x, half.x), draws.uniform(-half.y, half.y),
                                draws.uniform(-half.z, half.z)));
}

Real scaleOf(const Mat3& m)
{
    return std::max({std::abs(m[0][0]), std::abs(m[1][1]), std::abs(m[2][2])});
}

class Property : public ::testing::TestWithParam<int> {
protected:
    Draws draws{static_cast<std::uint64_t>(GetParam())};
};

TEST_P(Property, WorldInverseInertiaIsSymmetricPositiveDefiniteAndEqualsRotatedBodyInverse)
{
    World world;
    const BodyId id = world.createBody(randomBody(draws));
    const Body& body = world.body(id);
    const Mat3& inverse = body.invInertiaWorld;
    const Mat3 r = body.rotation();
    const Vec3 i0 = body.inertiaBody();
    const Mat3 expected = r * Mat3(Vec3(1.0 / i0.x, 0, 0), Vec3(0, 1.0 / i0.y, 0),
                                   Vec3(0, 0, 1.0 / i0.z)) *
                          glm::transpose(r);
    const Real scale = scaleOf(expected);
    EXPECT_LE(maxDifference(inverse, expected), 1e-12 * scale);
    EXPECT_LE(maxDifference(inverse, glm::transpose(inverse)), 1e-14 * scale);
    // Positive definite: x^T A x > 0 for random x, and the leading minors are positive.
    for (int i = 0; i < 10; ++i) {
        const Vec3 x = draws.vec3(-1.0, 1.0);
        EXPECT_GT(glm::dot(x, inverse * x), 0.0);
    }
    EXPECT_GT(inverse[0][0], 0.0);
    EXPECT_GT(inverse[0][0] * inverse[1][1] - inverse[0][1] * inverse[1][0], 0.0);
    EXPECT_GT(glm::determinant(inverse), 0.0);
    // And it is the inverse of the world inertia (to rounding times the condition number).
    const Mat3 product = inverse * body.inertiaWorld();
    const Real condition = std::max({i0.x, i0.y, i0.z}) / std::min({i0.x, i0.y, i0.z});
    EXPECT_LE(maxDifference(product, Mat3(1.0)), 1e-14 * condition);
}

TEST_P(Property, AnImpulseChangesMomentumByJAndAngularMomentumByRCrossJ)
{
    World world;
    const BodyId id = world.createBody(randomBody(draws));
    const Body before = world.body(id);
    const Vec3 point = pointInside(draws, before);
    const Vec3 impulse = draws.vec3(-1.0, 1.0) * before.mass * draws.logUniform(0.01, 100.0);
    world.applyImpulse(id, impulse, point);
    const Body& after = world.body(id);
    const Vec3 dp = after.linearMomentum() - before.linearMomentum();
    const Vec3 dl = after.angularMomentum() - before.angularMomentum();
    const Vec3 torque = glm::cross(point - before.position, impulse);
    const Real momentumScale = glm::length(before.linearMomentum()) + glm::length(impulse);
    const Real angularScale = glm::length(before.angularMomentum()) + glm::length(torque);
    EXPECT_LE(maxDifference(dp, impulse), 1e-12 * momentumScale);
    EXPECT_LE(maxDifference(dl, torque), 1e-10 * angularScale);
    EXPECT_EQ(after.position, before.position);
}

TEST_P(Property, AnImpactNeverIncreasesKineticEnergy)
{
    WorldSettings settings;
    World world(settings);
    world.setGround(Plane{});
    BodyDef def = randomBody(draws);
    def.position = Vec3(0.0);
    def.linearVelocity.y = -draws.uniform(0.1, 50.0);
    const BodyId id = world.createBody(def);
    // Just above the ground, so the first step or two hit it.
    Real lowest = 1e300;
    for (const Vec3& vertex : cuboidVertices(world.body(id).shape.halfExtents())) {
        lowest = std::min(lowest, world.body(id).worldPoint(vertex).y);
    }
    world.setTransform(id, Vec3(0.0, -lowest + draws.uniform(0.0, 0.01), 0.0), def.orientation);
    int impacts = 0;
    for (int step = 0; step < 2400 && impacts < 20; ++step) {
        world.step(1.0 / 240.0);
        for (const CollisionEvent& event : world.collisions()) {
            ++impacts;
            EXPECT_LE(event.kineticEnergyAfter,
                      event.kineticEnergyBefore * (1.0 + 1e-12) + 1e-300)
                << "impact " << impacts << " at t = " << event.time;
        }
    }
    EXPECT_GT(impacts, 0);
}

TEST_P(Property, ASolvedTargetIsReachedOrReportedImpossible)
{
    World world;
    const BodyId id = world.createBody(randomBody(draws));
    const Body& body = world.body(id);
    // A reachable target: the result of a random impulse at a random point of the body.
    const Vec3 point = pointInside(draws, body);
    const Vec3 impulse = draws.vec3(-1.0, 1.0) * body.mass * draws.logUniform(0.1, 10.0);
    Body pushed = body;
    pushed.linearVelocity += impulse / body.mass;
    pushed.angularVelocity += body.invInertiaWorld * glm::cross(point - body.position, impulse);
    const ImpulseTarget reachable =
        solveImpulseTarget(body, pushed.linearVelocity, pushed.angularVelocity);
    ASSERT_EQ(reachable.status, ImpulseTargetStatus::Reached) << describe(reachable.status);
    EXPECT_LE(maxDifference(reachable.impulse, impulse), 1e-9 * glm::length(impulse));

    // An arbitrary target: either reached (then applying it gets there) or a stated reason.
    const Vec3 targetVelocity = body.linearVelocity + draws.vec3(-5.0, 5.0);
    const Vec3 targetAngular = body.angularVelocity + draws.vec3(-5.0, 5.0);
    const ImpulseTarget solved = solveImpulseTarget(body, targetVelocity, targetAngular);
    if (solved.status == ImpulseTargetStatus::Reached) {
        world.applyImpulse(id, solved.impulse, body.position + solved.offset);
        EXPECT_LE(maxDifference(world.body(id).linearVelocity, targetVelocity), 1e-9);
        EXPECT_LE(maxDifference(world.body(id).angularVelocity, targetAngular), 1e-6);
    } else {
        EXPECT_STRNE(describe(solved.status), "");
        // A random 6-dof target almost never has the torque perpendicular to the impulse.
        EXPECT_EQ(solved.status, ImpulseTargetStatus::TorqueNotPerpendicular);
    }
}

INSTANTIATE_TEST_SUITE_P(Seeds, Property, ::testing::Range(0, kSeeds));

} // namespace
} // namespace tumble::robustness
