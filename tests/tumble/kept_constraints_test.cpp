// An island's constraints kept from step to step (docs/physics/11-island-solver.md, (11.6a)): kept
// while nothing they are made of moves, prepared again as soon as a body, a static box or a mass
// changes, and a stack solved with kept constraints stands as still as one prepared every step.
#include "tumble/world.hpp"

#include "support/test_world.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace tumble {
namespace {

constexpr Real kDt = 1.0 / 60.0;

/// `cubes` unit cubes of mass 1 stacked face to face on the ground, mu = 0.5, no bounce.
std::vector<BodyId> addStack(World& world, int cubes, Real base = 0.0)
{
    std::vector<BodyId> stack;
    for (int k = 0; k < cubes; ++k) {
        stack.push_back(world.createBody(
            BodyDef{.shape = Cuboid{Vec3(1.0)},
                    .position = Vec3(0.0, base + 0.5 + k, 0.0),
                    .material = Material{.restitution = 0.0, .friction = 0.5}}));
    }
    return stack;
}

/// Steps `steps` times and returns how many of them kept the island's constraints.
std::size_t keptSteps(World& world, int steps)
{
    std::size_t kept = 0;
    for (int step = 0; step < steps; ++step) {
        world.step(kDt);
        kept += world.solverStatistics().keptIslands;
    }
    return kept;
}

TEST(KeptConstraints, ASettledStackKeepsThemAndStandsStill)
{
    World world = testing::worldWithGround(WorldSettings{.allowSleep = false});
    const std::vector<BodyId> stack = addStack(world, 10);
    keptSteps(world, 60);
    // the cubes creep by about 1e-12 m a step: far inside (9.11) for most steps
    EXPECT_GE(keptSteps(world, 240), 200u);
    for (int k = 0; k < 10; ++k) {
        const Body& cube = world.body(stack[k]);
        EXPECT_NEAR(cube.position.x, 0.0, 1e-6);
        EXPECT_NEAR(cube.position.z, 0.0, 1e-6);
        EXPECT_NEAR(cube.position.y, 0.5 + k, 1e-4);
        EXPECT_LT(glm::length(cube.linearVelocity), 1e-6);
    }
}

TEST(KeptConstraints, AHeavierCubeIsPreparedAgainAndCarried)
{
    World world = testing::worldWithGround(WorldSettings{.allowSleep = false});
    const std::vector<BodyId> stack = addStack(world, 3);
    keptSteps(world, 60);
    ASSERT_EQ(keptSteps(world, 1), 1u);
    // the middle cube becomes 50 times heavier: its inverse mass and inertia change the rows
    world.setMass(stack[1], 50.0);
    EXPECT_EQ(keptSteps(world, 1), 0u);
    keptSteps(world, 60);
    // the ground now carries 52 kg at rest: nothing sinks or moves
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(world.body(stack[k]).position.y, 0.5 + k, 1e-4);
        EXPECT_LT(glm::length(world.body(stack[k]).linearVelocity), 1e-6);
    }
}

TEST(KeptConstraints, ABodyOrAStaticBoxThatMovesIsPreparedAgain)
{
    World world = testing::worldWithGround(WorldSettings{.allowSleep = false});
    const BodyId table = world.createBody(BodyDef{.motion = BodyMotion::Static,
                                                  .shape = Cuboid{Vec3(4.0, 1.0, 4.0)},
                                                  .position = Vec3(0.0, 0.5, 0.0)});
    const std::vector<BodyId> stack = addStack(world, 2, 1.0);
    keptSteps(world, 60);
    ASSERT_EQ(keptSteps(world, 1), 1u);
    // a cube moved sideways by a micrometre, a thousand times (9.11)'s reach
    const Body& top = world.body(stack[1]);
    world.setTransform(stack[1], top.position + Vec3(1e-6, 0.0, 0.0), top.orientation);
    EXPECT_EQ(keptSteps(world, 1), 0u);
    EXPECT_EQ(keptSteps(world, 1), 1u);
    // the table lowered by a micrometre: no dynamic body moved, but every point under the stack
    world.setTransform(table, Vec3(0.0, 0.5 - 1e-6, 0.0), Quat(1.0, 0.0, 0.0, 0.0));
    EXPECT_EQ(keptSteps(world, 1), 0u);
    keptSteps(world, 60);
    EXPECT_NEAR(world.body(stack[0]).position.y, 1.5 - 1e-6, 1e-5);
    EXPECT_LT(glm::length(world.body(stack[1]).linearVelocity), 1e-6);
}

TEST(KeptConstraints, AStackKeepingThemEndsWhereAFreshlyPreparedOneDoes)
{
    // the same stack stepped twice; in the second the top cube is moved 2e-9 m back and forth
    // before each step, beyond (9.11)'s reach of where its rows were made, so none are kept
    World kept = testing::worldWithGround(WorldSettings{.allowSleep = false});
    World fresh = testing::worldWithGround(WorldSettings{.allowSleep = false});
    const std::vector<BodyId> keptStack = addStack(kept, 5);
    const std::vector<BodyId> freshStack = addStack(fresh, 5);
    std::size_t freshKept = 0;
    for (int step = 0; step < 300; ++step) {
        kept.step(kDt);
        const Body& top = fresh.body(freshStack.back());
        const Real nudge = step % 2 == 0 ? -2e-9 : 2e-9;
        fresh.setTransform(freshStack.back(), top.position + Vec3(0.0, 0.0, nudge),
                           top.orientation);
        fresh.step(kDt);
        freshKept += fresh.solverStatistics().keptIslands;
    }
    EXPECT_EQ(freshKept, 0u);
    // (11.6a): kept rows are within 1e-8 m of fresh ones; the stacks agree far below that
    for (int k = 0; k < 5; ++k) {
        const Body& a = kept.body(keptStack[k]);
        const Body& b = fresh.body(freshStack[k]);
        EXPECT_NEAR(a.position.y, b.position.y, 1e-7);
        EXPECT_NEAR(a.position.x, b.position.x, 1e-7);
        EXPECT_NEAR(glm::length(a.linearVelocity - b.linearVelocity), 0.0, 1e-7);
    }
}

} // namespace
} // namespace tumble
