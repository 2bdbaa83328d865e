// Fast bodies among others: nothing tunnels at 1/60 s, and elastic bodies bouncing in a closed
// box keep their kinetic energy (docs/physics/11-island-solver.md, (11.4), (11.4a), (11.8)).
#include "tumble/world.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace tumble {
namespace {

constexpr Real kDt = 1.0 / 60.0;

TEST(NoTunnelling, ASmallCubeAt100MetresASecondBouncesOffABlock)
{
    // 1.67 m a step against a 1 m block: the block is met, and the head-on closed form (11.11)
    // holds, v = (m1 v1 - m2 e v1) / (m1 + m2) for the cube and (1 + e) m1 v1 / (m1 + m2)
    World world(WorldSettings{.gravity = Vec3(0.0), .allowSleep = false});
    const Material material{.restitution = 0.5, .friction = 0.3};
    const BodyId cube = world.createBody(BodyDef{.shape = Cuboid{Vec3(0.1)},
                                                 .mass = 1.0,
                                                 .position = Vec3(-3.0, 0.0, 0.0),
                                                 .linearVelocity = Vec3(100.0, 0.0, 0.0),
                                                 .material = material});
    const BodyId block = world.createBody(
        BodyDef{.shape = Cuboid{Vec3(1.0)}, .mass = 10.0, .material = material});
    for (int step = 0; step < 60; ++step) {
        world.step(kDt);
    }
    EXPECT_NEAR(world.body(cube).linearVelocity.x, (100.0 - 10.0 * 0.5 * 100.0) / 11.0, 1e-9);
    EXPECT_NEAR(world.body(block).linearVelocity.x, 1.5 * 100.0 / 11.0, 1e-9);
    EXPECT_LT(world.body(cube).position.x, world.body(block).position.x);
}

TEST(NoTunnelling, ACubeAt50MetresASecondBouncesOffAThinStaticWall)
{
    // 0.83 m a step against a 5 cm wall: it bounces back with e = 0.6, the larger of the pair's
    // restitutions (11.7)
    World world(WorldSettings{.gravity = Vec3(0.0), .allowSleep = false});
    const BodyId cube = world.createBody(
        BodyDef{.shape = Cuboid{Vec3(0.2)},
                .mass = 1.0,
                .position = Vec3(-3.0, 0.0, 0.0),
                .linearVelocity = Vec3(50.0, 0.0, 0.0),
                .material = Material{.restitution = 0.5, .friction = 0.3}});
    world.createBody(BodyDef{.motion = BodyMotion::Static,
                             .shape = Cuboid{Vec3(0.05, 2.0, 2.0)},
                             .material = Material{.restitution = 0.6, .friction = 0.3}});
    for (int step = 0; step < 60; ++step) {
        world.step(kDt);
    }
    EXPECT_NEAR(world.body(cube).linearVelocity.x, -30.0, 1e-9);
    EXPECT_LT(world.body(cube).position.x, -0.125);
}

TEST(ClosedBox, FiveElasticCubesKeepTheirKineticEnergyForTwentySeconds)
{
    // e = 1, no friction, no gravity, six planes around a 4 m box: Poisson's restitution
    // (11.4a) keeps the kinetic energy of every impact, however many points push at once
    World world(WorldSettings{.gravity = Vec3(0.0), .allowSleep = false});
    for (int axis = 0; axis < 3; ++axis) {
        for (const Real side : {-1.0, 1.0}) {
            Vec3 point(0.0);
            Vec3 normal(0.0);
            point[axis] = 2.0 * side;
            normal[axis] = -side;
            world.addPlane(StaticPlane{.point = point, .normal = normal});
        }
    }
    std::mt19937_64 random(3);
    std::uniform_real_distribution<Real> unit(-1.0, 1.0);
    std::vector<BodyId> cubes;
    for (int k = 0; k < 5; ++k) {
        cubes.push_back(world.createBody(BodyDef{
            .shape = Cuboid{Vec3(0.4)},
            .mass = 1.0,
            .position = Vec3(-1.2 + 0.6 * k, 0.1 * k - 0.2, 0.05 * k),
            .linearVelocity = 3.0 * Vec3(unit(random), unit(random), unit(random)),
            .angularVelocity = Vec3(unit(random), unit(random), unit(random)),
            .material = Material{.restitution = 1.0, .friction = 0.0}}));
    }
    const auto kinetic = [&] {
        Real sum = 0.0;
        for (const BodyId id : cubes) {
            sum += world.body(id).kineticEnergy();
        }
        return sum;
    };
    const Real start = kinetic();
    int impacts = 0;
    for (int step = 0; step < 20 * 60; ++step) {
        world.step(kDt);
        impacts += static_cast<int>(world.collisions().size());
    }
    EXPECT_NEAR(kinetic() / start, 1.0, 0.005);
    EXPECT_GT(impacts, 50);
    for (const BodyId id : cubes) {
        const Vec3& position = world.body(id).position;
        EXPECT_LT(std::max({std::abs(position.x), std::abs(position.y), std::abs(position.z)}),
                  2.0);
    }
}

} // namespace
} // namespace tumble
