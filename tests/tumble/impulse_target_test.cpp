// Solving for one impulse and point that reach a target velocity and spin
// (docs/physics/03-impulses.md, (3.3)-(3.5)); the handout part 2 task 2 experiments.
#include "tumble/impulse_target.hpp"

#include "tumble/world.hpp"

#include "support/glm_printers.hpp"
#include "support/test_world.hpp"

#include <gtest/gtest.h>

namespace tumble {
namespace {

using testing::handoutCuboid;
using testing::kExact;
using testing::near;

struct HandoutImpulseCase {
    const char* name;
    Vec3 velocity;
    Vec3 angularVelocity;
    Vec3 targetVelocity;
    Vec3 targetAngularVelocity;
};

void PrintTo(const HandoutImpulseCase& c, std::ostream* os) { *os << c.name; }

class HandoutImpulse : public ::testing::TestWithParam<HandoutImpulseCase> {};

TEST_P(HandoutImpulse, ReachesTheTargetExactlyWithAPointInsideTheBody)
{
    // Part 2 task 2: rb of mass 1, 2 x 6 x 2, no force; after 2 s one impulse.
    const HandoutImpulseCase& c = GetParam();
    World world(WorldSettings{.gravity = Vec3(0.0)});
    BodyDef def = handoutCuboid(1.0);
    def.linearVelocity = c.velocity;
    def.angularVelocity = c.angularVelocity;
    const BodyId id = world.createBody(def);
    testing::simulate(world, 2.0, 1.0 / 240.0);

    const Body& body = world.body(id);
    const ImpulseTarget solved = solveImpulseTarget(body, c.targetVelocity, c.targetAngularVelocity);
    ASSERT_EQ(solved.status, ImpulseTargetStatus::Reached) << describe(solved.status);
    const Vec3 local = glm::conjugate(body.orientation) * solved.offset;
    const Vec3 half = body.shape.halfExtents();
    EXPECT_LE(std::abs(local.x), half.x + 1e-12);
    EXPECT_LE(std::abs(local.y), half.y + 1e-12);
    EXPECT_LE(std::abs(local.z), half.z + 1e-12);

    world.applyImpulse(id, solved.impulse, body.position + solved.offset);
    EXPECT_TRUE(near(body.linearVelocity, c.targetVelocity, kExact));
    EXPECT_TRUE(near(body.angularVelocity, c.targetAngularVelocity, kExact));
}

INSTANTIATE_TEST_SUITE_P(
    PartTwoTaskTwo, HandoutImpulse,
    ::testing::Values(
        HandoutImpulseCase{"MoveLeft", Vec3(0), Vec3(0), Vec3(-1, 0, 0), Vec3(0)},
        HandoutImpulseCase{"MoveLeftSpinAnticlockwise", Vec3(0), Vec3(0), Vec3(-1, 0, 0),
                           Vec3(0, 0, 0.5)},
        HandoutImpulseCase{"Stop", Vec3(3, 0, 0), Vec3(0), Vec3(0), Vec3(0)},
        HandoutImpulseCase{"Reverse", Vec3(3, 0, 0), Vec3(0), Vec3(-3, 0, 0), Vec3(0)},
        HandoutImpulseCase{"StopAndSpinClockwise", Vec3(3, 0, 0), Vec3(0), Vec3(0),
                           Vec3(0, 0, -0.5)},
        HandoutImpulseCase{"StopMovingAndRotating", Vec3(3, 0, 0), Vec3(0, 0, 1), Vec3(0),
                           Vec3(0)}),
    [](const ::testing::TestParamInfo<HandoutImpulseCase>& param) { return param.param.name; });

TEST(ImpulseTarget, SpinningAnticlockwiseNeedsTheImpulseAboveTheCentreOfMass)
{
    // J = (-1, 0, 0), I dw = (0, 0, Iz w) with Iz = 1/12 (4 + 36) = 10/3 for m = 1:
    // r0 = J x (I dw) / |J|^2 = (0, Iz w, 0) = (0, 5/3, 0) for w = 0.5.
    World world(WorldSettings{.gravity = Vec3(0.0)});
    const BodyId id = world.createBody(handoutCuboid(1.0));
    const ImpulseTarget solved =
        solveImpulseTarget(world.body(id), Vec3(-1, 0, 0), Vec3(0, 0, 0.5));
    EXPECT_TRUE(near(solved.impulse, Vec3(-1, 0, 0), kExact));
    EXPECT_TRUE(near(solved.offset, Vec3(0, 5.0 / 3.0, 0), kExact));
}

TEST(ImpulseTarget, PartThreeTaskOneGivesTheIssueExampleImpulse)
{
    World world(WorldSettings{.gravity = Vec3(0.0)});
    BodyDef def = handoutCuboid(2.0);
    def.linearVelocity = Vec3(2, 0, 0);
    const BodyId id = world.createBody(def);
    const ImpulseTarget solved = solveImpulseTarget(world.body(id), Vec3(0), Vec3(0, 0, -0.6));
    ASSERT_EQ(solved.status, ImpulseTargetStatus::Reached);
    EXPECT_TRUE(near(solved.impulse, Vec3(-4, 0, 0), kExact));
    EXPECT_TRUE(near(solved.offset, Vec3(0, -1, 0), kExact));
}

TEST(ImpulseTarget, SpinWithoutVelocityChangeIsUnreachable)
{
    World world(WorldSettings{.gravity = Vec3(0.0)});
    const BodyId id = world.createBody(handoutCuboid(1.0));
    EXPECT_EQ(solveImpulseTarget(world.body(id), Vec3(0), Vec3(0, 0, 1)).status,
              ImpulseTargetStatus::SpinWithoutImpulse);
}

TEST(ImpulseTarget, TorqueAlongTheImpulseIsUnreachable)
{
    // Pushing along x while asking for spin about x: r x J is never parallel to J.
    World world(WorldSettings{.gravity = Vec3(0.0)});
    const BodyId id = world.createBody(handoutCuboid(1.0));
    EXPECT_EQ(solveImpulseTarget(world.body(id), Vec3(-1, 0, 0), Vec3(0.5, 0, 0)).status,
              ImpulseTargetStatus::TorqueNotPerpendicular);
}

TEST(ImpulseTarget, ALineOfActionOutsideTheBodyIsUnreachable)
{
    // A tiny push with a large spin needs r0 = (0, Iz w / |J|, 0) = (0, 10/3 * 5 / 0.01, 0):
    // far above the top face, and the line along x never enters the body.
    World world(WorldSettings{.gravity = Vec3(0.0)});
    const BodyId id = world.createBody(handoutCuboid(1.0));
    EXPECT_EQ(solveImpulseTarget(world.body(id), Vec3(-0.01, 0, 0), Vec3(0, 0, 5)).status,
              ImpulseTargetStatus::LineMissesBody);
}

TEST(ImpulseTarget, NoChangeNeedsNoImpulse)
{
    World world(WorldSettings{.gravity = Vec3(0.0)});
    BodyDef def = handoutCuboid(1.0);
    def.linearVelocity = Vec3(1, 2, 3);
    const BodyId id = world.createBody(def);
    const ImpulseTarget solved = solveImpulseTarget(world.body(id), Vec3(1, 2, 3), Vec3(0));
    EXPECT_EQ(solved.status, ImpulseTargetStatus::Reached);
    EXPECT_TRUE(near(solved.impulse, Vec3(0), 0.0));
}

} // namespace
} // namespace tumble
