// Long runs (10^6 steps): a cuboid resting on the ground does not drift, creep or jitter; a
// tumbling cuboid stays finite with a unit quaternion. TUMBLE_LONG_RUN_STEPS overrides the step
// count (tools/ci-sanitize.sh uses fewer under the sanitizers, which are ~20x slower).
#include "drop_case.hpp"

#include "tumble/world.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace tumble::robustness {
namespace {

long long longRunSteps()
{
    if (const char* steps = std::getenv("TUMBLE_LONG_RUN_STEPS")) {
        return std::stoll(steps);
    }
    return 1'000'000;
}

/// A 1 x 2 x 3 box (no two equal moments) lying on its largest face.
BodyDef restingBox()
{
    BodyDef def;
    def.shape.size = Vec3(3.0, 1.0, 2.0);
    def.mass = 2.0;
    def.position = Vec3(0.0, 0.5, 0.0);
    return def;
}

void expectRestsWithoutDrift(bool allowSleep)
{
    WorldSettings settings;
    settings.allowSleep = allowSleep;
    World world(settings);
    world.setGround(Plane{});
    const BodyId id = world.createBody(restingBox());
    const Body start = world.body(id);
    const Real energy0 = start.kineticEnergy() + start.potentialEnergy(settings.gravity);
    Real maxDrift = 0.0;
    Real maxSpeed = 0.0;
    Real maxEnergyChange = 0.0;
    const long long steps = longRunSteps();
    for (long long step = 0; step < steps; ++step) {
        world.step(1.0 / 240.0);
        const Body& body = world.body(id);
        maxDrift = std::max(maxDrift, glm::length(body.position - start.position));
        maxSpeed = std::max(maxSpeed, glm::length(body.linearVelocity) +
                                          glm::length(body.angularVelocity));
        maxEnergyChange = std::max(
            maxEnergyChange,
            std::abs(body.kineticEnergy() + body.potentialEnergy(settings.gravity) - energy0));
    }
    const Body& end = world.body(id);
    std::printf("resting box, %lld steps, sleep %s: max drift %.3g m, max speed %.3g, max energy "
                "change %.3g J, |q| - 1 = %.3g\n",
                steps, allowSleep ? "on" : "off", maxDrift, maxSpeed, maxEnergyChange,
                glm::length(end.orientation) - 1.0);
    EXPECT_LT(maxDrift, 1e-6);
    EXPECT_LT(maxSpeed, 1e-6) << "jitter";
    EXPECT_LT(maxEnergyChange, 1e-6) << "energy creep";
    EXPECT_LT(std::abs(glm::length(end.orientation) - 1.0), 1e-12);
}

TEST(LongRun, RestingCuboidDoesNotDriftWithSleep) { expectRestsWithoutDrift(true); }

TEST(LongRun, RestingCuboidDoesNotDriftOrJitterWithoutSleep) { expectRestsWithoutDrift(false); }

TEST(LongRun, TumblingCuboidStaysFiniteWithAUnitQuaternion)
{
    // Torque-free (no gravity, no ground): an asymmetric box spinning near its unstable middle
    // axis, so it flips over and over for the whole run.
    WorldSettings settings;
    settings.gravity = Vec3(0.0);
    World world(settings);
    BodyDef def;
    def.shape.size = Vec3(1.0, 2.0, 3.0);
    def.angularVelocity = Vec3(0.01, 3.0, 0.02);
    const BodyId id = world.createBody(def);
    const Vec3 momentum0 = world.body(id).angularMomentum();
    const Real energy0 = world.body(id).kineticEnergy();
    Real maxQuaternionError = 0.0;
    Real maxEnergyError = 0.0;
    Real maxMomentumError = 0.0;
    bool finite = true;
    const long long steps = longRunSteps();
    for (long long step = 0; step < steps && finite; ++step) {
        world.step(1.0 / 240.0);
        const Body& body = world.body(id);
        finite = isFiniteState(body);
        maxQuaternionError =
            std::max(maxQuaternionError, std::abs(glm::length(body.orientation) - 1.0));
        maxEnergyError = std::max(maxEnergyError, std::abs(body.kineticEnergy() - energy0) / energy0);
        maxMomentumError = std::max(
            maxMomentumError, glm::length(body.angularMomentum() - momentum0) / glm::length(momentum0));
    }
    std::printf("tumbling box, %lld steps: max | |q| - 1 | = %.3g, max relative energy error "
                "%.3g, max relative angular momentum error %.3g\n",
                steps, maxQuaternionError, maxEnergyError, maxMomentumError);
    EXPECT_TRUE(finite);
    EXPECT_LE(maxQuaternionError, 1e-12);
    // Second order in |w| dt = 0.0125 rad, no drift.
    EXPECT_LE(maxEnergyError, 1e-4);
    EXPECT_LE(maxMomentumError, 1e-9);
}

} // namespace
} // namespace tumble::robustness
