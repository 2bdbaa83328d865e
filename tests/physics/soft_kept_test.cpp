// The soft step's kept manifolds (docs/physics/12-soft-step.md, (12.5b)): an island whose bodies
// stayed put steps on last step's manifolds, rows and impulses, and stands as the island that
// builds them every step does; an edit, a body joining or a body moving ends them.
#include "tumble/state_hash.hpp"
#include "tumble/world.hpp"

#include "support/slope_world.hpp"
#include "support/test_world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace tumble {
namespace {

constexpr Real kGravity = 9.81;
constexpr Real kDt = 1.0 / 60.0;

WorldSettings softSettings()
{
    return WorldSettings{.solver = ContactSolver::Soft, .allowSleep = false};
}

BodyDef unitCube(const Vec3& position)
{
    return BodyDef{.shape = Cuboid{Vec3(1.0)},
                   .position = position,
                   .material = Material{.restitution = 0.0, .friction = 0.5}};
}

/// A column of `count` unit cubes of mass 1 on the ground, face to face.
std::vector<BodyId> addColumn(World& world, int count)
{
    std::vector<BodyId> cubes;
    for (int i = 0; i < count; ++i) {
        cubes.push_back(world.createBody(unitCube(Vec3(0.0, 0.5 + i, 0.0))));
    }
    return cubes;
}

/// A floor of side x side unit cubes on the ground, side by side: 2 side (side - 1) faces
/// between cubes and side x side on the ground, enough manifolds for the lanes (12.9).
std::vector<BodyId> addFloor(World& world, int side)
{
    std::vector<BodyId> cubes;
    for (int i = 0; i < side; ++i) {
        for (int k = 0; k < side; ++k) {
            cubes.push_back(world.createBody(unitCube(Vec3(i, 0.5, k))));
        }
    }
    return cubes;
}

/// (12.2a): the gap a spring of `hertz` holds under `force` at effective mass m, F / (m w^2).
Real springGap(Real force, Real effectiveMass, Real hertz)
{
    const Real omega = 2.0 * std::numbers::pi * hertz;
    return force / (effectiveMass * omega * omega);
}

std::vector<Vec3> positionsOf(const World& world, const std::vector<BodyId>& bodies)
{
    std::vector<Vec3> positions;
    for (const BodyId body : bodies) {
        positions.push_back(world.body(body).position);
    }
    return positions;
}

/// Steps `steps` times and counts the steps whose one island kept its manifolds.
int keptSteps(World& world, int steps)
{
    int kept = 0;
    for (int s = 0; s < steps; ++s) {
        world.step(kDt);
        kept += world.solverStatistics().keptIslands == 1 ? 1 : 0;
    }
    return kept;
}

TEST(SoftKept, ASettledColumnKeepsItsManifoldsAndStaysOnItsSprings)
{
    World world = testing::worldWithGround(softSettings());
    const std::vector<BodyId> cubes = addColumn(world, 5);
    testing::simulate(world, 3.0, kDt);
    const std::vector<Vec3> settled = positionsOf(world, cubes);
    EXPECT_EQ(keptSteps(world, 600), 600);
    // (12.2a) as for a column that builds its manifolds every step: the ground's corners of
    // effective mass 1/4 carry 5 g / 4 each on 60 Hz springs (soft_step_test.cpp)
    const Real groundGap = springGap(5 * kGravity / 4.0, 0.25, 60.0);
    EXPECT_NEAR(0.5 - world.body(cubes[0]).position.y, groundGap, 0.02 * groundGap);
    for (std::size_t i = 0; i < cubes.size(); ++i) {
        const Body& cube = world.body(cubes[i]);
        EXPECT_LT(std::hypot(cube.position.x, cube.position.z), 1e-3) << i;
        EXPECT_LT(glm::length(cube.position - settled[i]), 1e-6) << i;
        EXPECT_LT(glm::length(cube.linearVelocity), 1e-6) << i;
    }
}

TEST(SoftKept, AFloorInLanesKeepsItsManifoldsAndDoesNotCreep)
{
    World world = testing::worldWithGround(softSettings());
    const std::vector<BodyId> cubes = addFloor(world, 6);
    testing::simulate(world, 2.0, kDt);
    const std::vector<Vec3> settled = positionsOf(world, cubes);
    EXPECT_EQ(keptSteps(world, 600), 600);
    const Real groundGap = springGap(kGravity / 4.0, 0.25, 60.0);
    for (std::size_t i = 0; i < cubes.size(); ++i) {
        const Vec3& p = world.body(cubes[i]).position;
        EXPECT_LT(glm::length(p - settled[i]), 1e-6) << i;
        EXPECT_NEAR(0.5 - p.y, groundGap, 0.02 * groundGap) << i;
    }
}

TEST(SoftKept, ABoxHoldingOnASlopeKeepsItsManifoldAndDoesNotCreep)
{
    // (6.6): mu = 0.5 > tan 20 deg, so the box holds; kept steps choose the static coefficient
    // from the velocities now, as built ones do
    testing::Slope slope = testing::makeSlope(20.0, 0.5, 1.0, 1.0, softSettings());
    testing::simulate(slope.world, 1.0, kDt);
    const Vec3 held = slope.world.body(slope.box).position;
    EXPECT_EQ(keptSteps(slope.world, 600), 600);
    EXPECT_LT(glm::length(slope.world.body(slope.box).position - held), 1e-6);
}

TEST(SoftKept, CubesOnStaticBlocksKeepTheirManifoldsWhicheverSideIsTheLowerSlot)
{
    // a pair is kept under its lower slot: the first block comes before its column (a static
    // lower side), the second after its cube (a dynamic one); each island keeps its manifolds,
    // with every pair touching and none moving
    World world(softSettings());
    const auto block = [&](Real x) {
        return world.createBody(BodyDef{.motion = BodyMotion::Static,
                                        .shape = Cuboid{Vec3(2.0, 1.0, 2.0)},
                                        .position = Vec3(x, -0.5, 0.0)});
    };
    block(0.0);
    const std::vector<BodyId> cubes{world.createBody(unitCube(Vec3(0.0, 0.5, 0.0))),
                                    world.createBody(unitCube(Vec3(0.0, 1.5, 0.0))),
                                    world.createBody(unitCube(Vec3(4.0, 0.5, 0.0)))};
    block(4.0);
    testing::simulate(world, 3.0, kDt);
    const std::vector<Vec3> settled = positionsOf(world, cubes);
    for (int s = 0; s < 60; ++s) {
        world.step(kDt);
        ASSERT_EQ(world.solverStatistics().islands, 2u) << s;
        ASSERT_EQ(world.solverStatistics().keptIslands, 2u) << s;
        // four corners on each block and four on the face between the column's cubes
        ASSERT_EQ(world.solverStatistics().contactPoints, 12u) << s;
    }
    for (std::size_t i = 0; i < cubes.size(); ++i) {
        EXPECT_LT(glm::length(world.body(cubes[i]).position - settled[i]), 1e-6) << i;
    }
}

TEST(SoftKept, ASlidingBoxBuildsItsManifoldEveryStep)
{
    // tan 30 deg > mu = 0.3: it slides, moving more than the bound every step
    testing::Slope slope = testing::makeSlope(30.0, 0.3, 1.0, 1.0, softSettings());
    testing::simulate(slope.world, 0.5, kDt);
    EXPECT_EQ(keptSteps(slope.world, 60), 0);
}

TEST(SoftKept, AnEditEndsTheKeptManifoldsForOneStep)
{
    World world = testing::worldWithGround(softSettings());
    const std::vector<BodyId> cubes = addColumn(world, 3);
    testing::simulate(world, 3.0, kDt);
    ASSERT_EQ(keptSteps(world, 1), 1);
    // a velocity set by hand, even the one it has, may come with any change: built again
    world.setLinearVelocity(cubes[2], world.body(cubes[2]).linearVelocity);
    EXPECT_EQ(keptSteps(world, 1), 0);
    EXPECT_EQ(keptSteps(world, 1), 1);
}

TEST(SoftKept, ABodyJoiningAKeptIslandFindsEveryPairsPoints)
{
    World world = testing::worldWithGround(softSettings());
    const std::vector<BodyId> cubes = addColumn(world, 3);
    testing::simulate(world, 3.0, kDt);
    ASSERT_EQ(keptSteps(world, 1), 1);
    const std::size_t columnPoints = world.solverStatistics().contactPoints;
    // the ground's four corners and four a face between cubes, answered from the kept island
    EXPECT_EQ(columnPoints, 12u);
    const BodyId dropped = world.createBody(unitCube(Vec3(0.0, 3.6, 0.0)));
    bool joined = false;
    for (int s = 0; s < 60 && !joined; ++s) {
        world.step(kDt);
        if (world.solverStatistics().islands == 1 && world.solverStatistics().keptIslands == 0 &&
            world.solverStatistics().bodies == 4) {
            joined = true;
            // the column's pairs keep their points as the new pair's are found
            EXPECT_GE(world.solverStatistics().contactPoints, columnPoints + 1);
        }
    }
    ASSERT_TRUE(joined);
    testing::simulate(world, 3.0, kDt);
    EXPECT_NEAR(world.body(dropped).position.y, 3.5, 0.01);
    EXPECT_EQ(keptSteps(world, 60), 60);
}

TEST(SoftKept, ManifoldsBuiltAgainStartFromTheImpulsesTheKeptStepsLeft)
{
    // a settled column kept step after step, then built again (an edit): the step that builds
    // its manifolds starts from the impulses in its owners' caches, which the kept steps' must
    // reach (the settled load differs from the last built step's by less than this test sees;
    // with no impulses kept at all the column sags)
    World world = testing::worldWithGround(softSettings());
    const std::vector<BodyId> cubes = addColumn(world, 5);
    testing::simulate(world, 3.0, kDt);
    ASSERT_EQ(keptSteps(world, 1), 1);
    const Real top = world.body(cubes.back()).position.y;
    world.setLinearVelocity(cubes.back(), world.body(cubes.back()).linearVelocity);
    ASSERT_EQ(keptSteps(world, 1), 0);
    // started from the full load, the column does not move
    EXPECT_NEAR(world.body(cubes.back()).position.y, top, 1e-6);
}

TEST(SoftKept, ACopiedWorldKeepsWhatTheOriginalKeptAndStepsTheSameBits)
{
    World world = testing::worldWithGround(softSettings());
    addFloor(world, 6);
    testing::simulate(world, 2.0, kDt);
    ASSERT_EQ(keptSteps(world, 1), 1);
    World copy = world;
    EXPECT_EQ(keptSteps(copy, 60), 60);
    EXPECT_EQ(keptSteps(world, 60), 60);
    EXPECT_EQ(stateHash(copy), stateHash(world));
}

/// Two layers of 10 x 10 unit cubes, the upper shifted by a third of a cube, dropped 5 cm onto
/// each other and the ground: one island of some 600 pairs, which takes all the threads inside
/// its step (11.5c).
World twoLayers(int threads)
{
    WorldSettings settings = softSettings();
    settings.threads = threads;
    World world = testing::worldWithGround(settings);
    for (int layer = 0; layer < 2; ++layer) {
        for (int i = 0; i < 100; ++i) {
            const Real x = (i % 10) * 1.0 - 4.5 + layer / 3.0;
            const Real z = (i / 10) * 1.0 - 4.5;
            world.createBody(unitCube(Vec3(x, 0.55 + 1.05 * layer, z)));
        }
    }
    return world;
}

TEST(SoftKept, KeptStepsOfALargeIslandGiveTheSameBitsOnOneAndTwoThreads)
{
    // settling, kept, then joined by a dropped cube and kept again: the same bits throughout
    std::vector<World> worlds;
    std::vector<int> kept;
    for (const int threads : {1, 2}) {
        World world = twoLayers(threads);
        testing::simulate(world, 2.0, kDt);
        int keptCount = keptSteps(world, 60);
        world.createBody(unitCube(Vec3(0.2, 2.8, 0.1)));
        keptCount += keptSteps(world, 120);
        worlds.push_back(world);
        kept.push_back(keptCount);
    }
    EXPECT_GT(kept[0], 100);
    EXPECT_EQ(kept[0], kept[1]);
    EXPECT_EQ(stateHash(worlds[0]), stateHash(worlds[1]));
}

TEST(SoftKept, AnIslandSplitInHalvesGivesTheSameBitsOnAnyThreadCount)
{
    // (12.9): a floor of 24 x 24 cubes has more than 1 024 manifolds, so its bodies' halves are
    // swept a thread each; a row of cubes dropped across it keeps the island moving
    std::vector<World> worlds;
    std::vector<BodyId> cubes;
    for (const int threads : {1, 2, 3}) {
        WorldSettings settings = softSettings();
        settings.threads = threads;
        World world = testing::worldWithGround(settings);
        cubes = addFloor(world, 24);
        for (int i = 0; i < 20; ++i) {
            cubes.push_back(world.createBody(unitCube(Vec3(1.5 + i, 1.8, 11.5 - 0.5 * i))));
        }
        for (int s = 0; s < 90; ++s) {
            world.step(kDt);
        }
        // at least 1 024 manifolds of at most four points in the one island
        EXPECT_GT(world.solverStatistics().contactPoints, 4u * 1024u);
        EXPECT_EQ(world.solverStatistics().islands, 1u);
        worlds.push_back(world);
    }
    EXPECT_EQ(stateHash(worlds[0]), stateHash(worlds[1]));
    EXPECT_EQ(stateHash(worlds[0]), stateHash(worlds[2]));
    // the island's work, kinetic energy and mass are summed half by half (12.8), so each body's
    // ledger has the same bits too
    for (const World& other : {worlds[1], worlds[2]}) {
        for (const BodyId cube : cubes) {
            const EnergyLedger& one = worlds[0].body(cube).ledger;
            const EnergyLedger& more = other.body(cube).ledger;
            ASSERT_EQ(one.removedByNormal, more.removedByNormal);
            ASSERT_EQ(one.removedByFriction, more.removedByFriction);
            ASSERT_EQ(one.exchanged, more.exchanged);
            ASSERT_EQ(one.removedByIntegration, more.removedByIntegration);
        }
    }
}

} // namespace
} // namespace tumble
