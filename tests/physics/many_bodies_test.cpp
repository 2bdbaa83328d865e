// Many bodies in one world: a batched, threaded step gives each body exactly the trajectory it
// has alone in a world of its own, whatever the number of threads.
#include "tumble/scenario/scenario.hpp"
#include "tumble/world.hpp"

#include "support/test_world.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace tumble {
namespace {

/// The S4 benchmark's bodies (docs/scenario-format.md, [[spawn]]): 2 x 6 x 2 cuboids, random
/// orientations, spins up to 2 rad/s, heights 4..10 m, elasticity 0.6, friction 0.5.
std::vector<scenario::BodySpec> tumblingCuboids(std::size_t count)
{
    scenario::SpawnSpec spawn;
    spawn.count = count;
    spawn.seed = 1;
    // far enough apart that no two ever touch: each then moves as it would alone
    spawn.spacing = 40.0;
    spawn.body.shape.size = Vec3(2, 6, 2);
    spawn.body.mass = 2.0;
    spawn.heightLow = 4.0;
    spawn.heightHigh = 10.0;
    spawn.randomOrientation = true;
    spawn.angularSpeedHigh = 2.0;
    return scenario::spawnBodies(spawn, 0.0, "s");
}

World worldOf(const std::vector<scenario::BodySpec>& bodies, int threads)
{
    World world = testing::worldWithGround(WorldSettings{.threads = threads});
    for (const scenario::BodySpec& body : bodies) {
        world.createBody(body.def);
    }
    return world;
}

/// Every field the next step depends on, compared bit for bit.
void expectSameState(const Body& a, const Body& b, std::size_t body, long step)
{
    ASSERT_EQ(a.position, b.position) << "body " << body << " step " << step;
    ASSERT_EQ(a.orientation, b.orientation) << "body " << body << " step " << step;
    ASSERT_EQ(a.linearVelocity, b.linearVelocity) << "body " << body << " step " << step;
    ASSERT_EQ(a.angularVelocity, b.angularVelocity) << "body " << body << " step " << step;
    ASSERT_EQ(a.asleep, b.asleep) << "body " << body << " step " << step;
}

constexpr Real kDt = 1.0 / 240.0;

TEST(ManyBodies, BatchedStepGivesEachBodyItsScalarTrajectory)
{
    // 100 bodies fill several batches of the threaded step; each also runs alone (the scalar
    // path: a world of one body on one thread). 4 s covers the fall, the bounces and the rest.
    const std::vector<scenario::BodySpec> bodies = tumblingCuboids(100);
    World batched = worldOf(bodies, 2);
    const std::vector<BodyId> batchedIds = batched.bodyIds();
    std::vector<World> scalar;
    for (const scenario::BodySpec& body : bodies) {
        scalar.push_back(worldOf({body}, 1));
    }
    std::vector<int> batchedImpacts(bodies.size(), 0);
    std::vector<int> scalarImpacts(bodies.size(), 0);
    std::size_t resting = 0;
    for (long step = 0; step < 960; ++step) {
        batched.step(kDt);
        for (const CollisionEvent& event : batched.collisions()) {
            ++batchedImpacts[event.manifold.body.index];
        }
        resting += batched.restEvents().size();
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            scalar[i].step(kDt);
            scalarImpacts[i] += static_cast<int>(scalar[i].collisions().size());
            expectSameState(batched.body(batchedIds[i]), scalar[i].body(scalar[i].bodyIds()[0]),
                            i, step);
        }
    }
    EXPECT_EQ(batchedImpacts, scalarImpacts);
    // The scene is not trivial: every body hit the ground and a good part came to rest.
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        EXPECT_GT(batchedImpacts[i], 0) << i;
    }
    EXPECT_GT(resting, bodies.size() / 4);
}

TEST(ManyBodies, ResultsAndEventOrderDoNotDependOnTheThreadCount)
{
    const std::vector<scenario::BodySpec> bodies = tumblingCuboids(100);
    std::vector<World> worlds;
    for (const int threads : {1, 2, 3, 8}) {
        worlds.push_back(worldOf(bodies, threads));
    }
    for (long step = 0; step < 600; ++step) {
        for (World& world : worlds) {
            world.step(kDt);
        }
        const World& reference = worlds[0];
        for (std::size_t w = 1; w < worlds.size(); ++w) {
            const World& other = worlds[w];
            ASSERT_EQ(other.collisions().size(), reference.collisions().size()) << step;
            for (std::size_t e = 0; e < reference.collisions().size(); ++e) {
                EXPECT_EQ(other.collisions()[e].manifold.body, reference.collisions()[e].manifold.body);
                EXPECT_EQ(other.collisions()[e].time, reference.collisions()[e].time);
                EXPECT_EQ(other.collisions()[e].normalImpulse, reference.collisions()[e].normalImpulse);
            }
            ASSERT_EQ(other.restEvents().size(), reference.restEvents().size()) << step;
            for (std::size_t e = 0; e < reference.restEvents().size(); ++e) {
                EXPECT_EQ(other.restEvents()[e].body, reference.restEvents()[e].body);
                EXPECT_EQ(other.restEvents()[e].time, reference.restEvents()[e].time);
            }
            const std::vector<BodyId> ids = reference.bodyIds();
            for (std::size_t i = 0; i < ids.size(); ++i) {
                expectSameState(reference.body(ids[i]), other.body(ids[i]), i, step);
            }
        }
    }
}

TEST(ManyBodies, ThreadCountZeroMeansOnePerCore)
{
    World world(WorldSettings{.threads = 0});
    EXPECT_GE(world.threadCount(), 1);
    world.setThreads(3);
    EXPECT_EQ(world.threadCount(), 3);
}

} // namespace
} // namespace tumble
