// What an island's solve costs and how it spreads over threads: a settled pyramid takes one
// sweep a step, a plastic impact one solve, and a large island the same states on any number
// of threads (docs/physics/11-island-solver.md, (11.4a), (11.5a), (11.5c)).
#include "tumble/world.hpp"

#include "dynamics/island_solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace tumble {
namespace {

/// Jolt's pyramid scene with `layers` layers: cubes of size 2, 8000 kg, mu = 0.2, e = 0, layer i
/// at height 1 + spacing i (Jolt's 2.5: each layer falls 0.5 m onto the one below; 2: resting
/// on it). With `staticBase` the bottom layer is static boxes. Returns the cube count.
std::size_t buildPyramid(World& world, int layers, Real spacing, bool staticBase = false)
{
    world.setGround(Plane{});
    std::size_t cubes = 0;
    for (int i = 0; i < layers; ++i) {
        const Real shift = i % 2 == 1 ? 1.0 : 0.0;
        for (int j = i / 2; j < layers - (i + 1) / 2; ++j) {
            for (int k = i / 2; k < layers - (i + 1) / 2; ++k) {
                world.createBody(BodyDef{
                    .motion = staticBase && i == 0 ? BodyMotion::Static : BodyMotion::Dynamic,
                    .shape = Cuboid{Vec3(2.0)},
                    .mass = 8000.0,
                    .position = Vec3(-layers + 2 * j + shift, 1.0 + spacing * i,
                                     -layers + 2 * k + shift),
                    .material = Material{.restitution = 0.0, .friction = 0.2}});
                ++cubes;
            }
        }
    }
    return cubes;
}

TEST(IslandSolverCost, ASettledPyramidCostsOneSweepAStep)
{
    // five layers, 55 cubes: once settled, last step's impulses are this step's answer (11.6),
    // and the points that come and go as corners touch start from zero (11.13)
    World world(WorldSettings{.allowSleep = false});
    const std::size_t cubes = buildPyramid(world, 5, 2.5);
    for (int step = 0; step < 180; ++step) {
        world.step(1.0 / 60);
    }
    std::size_t sweeps = 0;
    for (int step = 0; step < 60; ++step) {
        world.step(1.0 / 60);
        const SolverStatistics& statistics = world.solverStatistics();
        EXPECT_EQ(statistics.bodies, cubes);
        EXPECT_EQ(statistics.solves, 1u) << "no impact and no cut: one sub-step solve";
        sweeps += statistics.sweeps;
    }
    EXPECT_LE(sweeps, 2u * 60u);
}

TEST(IslandSolverCost, APlasticImpactTakesOneSolveAndStopsTheApproach)
{
    // (11.4a): a cube pressed onto a resting cube at 1 m/s with e = 0 gets its compression and no
    // restitution share, so no second, plastic pass: one impact solve and the sub-step's solve.
    // The base's contact with the ground is in contact too, so the impact stops both cubes.
    World world(WorldSettings{.allowSleep = false});
    world.setGround(Plane{});
    const Material plastic{.restitution = 0.0, .friction = 0.5};
    const BodyId base = world.createBody(BodyDef{
        .shape = Cuboid{Vec3(1.0)}, .position = Vec3(0.0, 0.5, 0.0), .material = plastic});
    const BodyId top = world.createBody(BodyDef{.shape = Cuboid{Vec3(1.0)},
                                                .position = Vec3(0.0, 1.5, 0.0),
                                                .linearVelocity = Vec3(0.0, -1.0, 0.0),
                                                .material = plastic});
    world.step(1.0 / 240);
    const SolverStatistics& statistics = world.solverStatistics();
    EXPECT_EQ(statistics.islands, 1u);
    EXPECT_EQ(statistics.substeps, 1u);
    EXPECT_EQ(statistics.solves, 2u) << "the compression and the sub-step, nothing else";
    const Real approach = world.body(top).linearVelocity.y - world.body(base).linearVelocity.y;
    EXPECT_NEAR(approach, 0.0, 1e-9);
    EXPECT_NEAR(world.body(top).linearVelocity.y, 0.0, 1e-9) << "the ground holds both";
}

/// Steps a nine-layer pyramid resting on itself (285 cubes, over 6000 points), struck on its top
/// by a spinning cube, on one thread and on two, and expects the same states and sweep counts
/// after every step (11.5c). With `staticBase` its bottom layer is static boxes, whose pairs
/// the dynamic body of each keeps (9.11).
void expectTheSameStatesOnOneAndTwoThreads(bool staticBase)
{
    std::vector<World> worlds;
    for (const int threads : {1, 2}) {
        World& world = worlds.emplace_back(WorldSettings{.allowSleep = false, .threads = threads});
        buildPyramid(world, 9, 2.0, staticBase);
        world.createBody(BodyDef{
            .shape = Cuboid{Vec3(1.0)},
            .mass = 8000.0,
            .position = Vec3(0.3, 2.0 * 9 + 0.65, -0.2),
            .orientation = axisAngle(glm::normalize(Vec3(1.0, 0.2, 0.4)), 0.1),
            .linearVelocity = Vec3(0.5, -4.0, 0.0),
            .angularVelocity = Vec3(1.0, 0.0, 2.0),
            .material = Material{.restitution = 0.5, .friction = 0.2}});
    }
    std::size_t largestIsland = 0;
    std::size_t collisions = 0;
    for (int step = 0; step < 8; ++step) {
        for (World& world : worlds) {
            world.step(1.0 / 60);
        }
        const World& reference = worlds[0];
        largestIsland = std::max(largestIsland, reference.solverStatistics().contactPoints);
        collisions += reference.collisions().size();
        const World& other = worlds[1];
        ASSERT_EQ(other.solverStatistics().sweeps, reference.solverStatistics().sweeps) << step;
        for (const BodyId id : reference.bodyIds()) {
            ASSERT_EQ(other.body(id).position, reference.body(id).position) << step;
            ASSERT_EQ(other.body(id).orientation, reference.body(id).orientation) << step;
            ASSERT_EQ(other.body(id).linearVelocity, reference.body(id).linearVelocity) << step;
            ASSERT_EQ(other.body(id).angularVelocity, reference.body(id).angularVelocity) << step;
        }
    }
    const std::size_t lowest = staticBase ? 4u : 6u;
    EXPECT_GE(largestIsland, lowest * kColouredSweepPoints) << "the coloured sweeps ran";
    EXPECT_GE(collisions, 1u) << "the dropped cube struck the pyramid";
}

TEST(IslandThreads, ALargeIslandGivesTheSameStatesOnAnyThreadCount)
{
    // one island of more points than kColouredSweepPoints, swept colour by colour, and on two
    // threads each colour, the narrow phase and the warm start split between them
    expectTheSameStatesOnOneAndTwoThreads(false);
}

TEST(IslandThreads, ALargeIslandOnStaticBoxesGivesTheSameStatesOnAnyThreadCount)
{
    // the pairs of a static box go to the thread of their dynamic body, which may own other
    // pairs too (step/owner_groups.hpp)
    expectTheSameStatesOnOneAndTwoThreads(true);
}

TEST(IslandThreads, ALandedPyramidStandsInItsColumns)
{
    // six layers, 91 cubes, each layer dropped 0.5 m onto the one below (more than
    // kColouredSweepPoints points once landed): after 1.5 s every cube is at rest in its column
    World world(WorldSettings{.allowSleep = false});
    buildPyramid(world, 6, 2.5);
    std::size_t largestIsland = 0;
    for (int step = 0; step < 90; ++step) {
        world.step(1.0 / 60);
        largestIsland = std::max(largestIsland, world.solverStatistics().contactPoints);
    }
    EXPECT_GE(largestIsland, kColouredSweepPoints) << "the coloured sweeps ran";
    for (const BodyId id : world.bodyIds()) {
        const Body& body = world.body(id);
        EXPECT_LT(glm::length(body.linearVelocity), 1e-3);
        const Real x = body.position.x + 6.0;
        const Real z = body.position.z + 6.0;
        EXPECT_NEAR(x, std::round(x), 1e-3);
        EXPECT_NEAR(z, std::round(z), 1e-3);
    }
}

} // namespace
} // namespace tumble
