// Energy never grows without input: seeded random throws with any restitution in [0, 1] and any
// friction (docs/physics/05-normal-impulse.md, (5.6)).
#include "tumble/world.hpp"

#include "support/test_world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

namespace tumble {
namespace {

using testing::totalEnergy;

/// Uniform in [low, high) from the top 53 bits: the same on every standard library.
Real uniform(std::mt19937_64& generator, Real low, Real high)
{
    const Real unit = static_cast<Real>(generator() >> 11) * 0x1.0p-53;
    return low + (high - low) * unit;
}

Vec3 uniformVector(std::mt19937_64& generator, Real magnitude)
{
    return Vec3(uniform(generator, -magnitude, magnitude), uniform(generator, -magnitude, magnitude),
                uniform(generator, -magnitude, magnitude));
}

class RandomThrow : public ::testing::TestWithParam<int> {};

TEST_P(RandomThrow, TotalEnergyNeverGrowsAndImpactsNeverAddKineticEnergy)
{
    std::mt19937_64 generator(static_cast<std::uint64_t>(GetParam()));
    const Vec3 size(uniform(generator, 0.2, 3.0), uniform(generator, 0.2, 3.0),
                    uniform(generator, 0.2, 3.0));
    World world = testing::worldWithGround();
    BodyDef def;
    def.shape.size = size;
    def.mass = uniform(generator, 0.1, 10.0);
    def.position = Vec3(0, 2.0 + glm::length(size), 0);
    def.orientation = glm::normalize(Quat(uniform(generator, -1, 1), uniform(generator, -1, 1),
                                          uniform(generator, -1, 1), uniform(generator, -1, 1)));
    def.linearVelocity = uniformVector(generator, 3.0);
    def.angularVelocity = uniformVector(generator, 8.0);
    def.material = {.restitution = uniform(generator, 0.0, 1.0),
                    .friction = uniform(generator, 0.0, 1.5)};
    const BodyId id = world.createBody(def);
    const Real energy0 = totalEnergy(world, id);
    // Energy is measured from the ground: potential m g y with y >= the lowest half extent.
    const Real scale = energy0 + def.mass * 9.81 * glm::length(size);
    Real highest = energy0;
    testing::simulate(world, 8.0, 1.0 / 240.0, [&](const World& w) {
        highest = std::max(highest, totalEnergy(w, id));
        for (const CollisionEvent& event : w.collisions()) {
            EXPECT_LE(event.kineticEnergyAfter,
                      event.kineticEnergyBefore * (1 + 1e-12) + 1e-15);
        }
        const Body& body = w.body(id);
        ASSERT_TRUE(isFinite(body.position) && isFinite(body.linearVelocity) &&
                    isFinite(body.angularVelocity));
    });
    // Free flight is exact in translation and second order in rotation; the penetration
    // correction can add m g d with d below the contact tolerance.
    EXPECT_LE(highest - energy0, 1e-4 * scale);
}

INSTANTIATE_TEST_SUITE_P(Seeds, RandomThrow, ::testing::Range(1, 41));

} // namespace
} // namespace tumble
