// Micro benchmarks: cuboid-plane detection, one contact solve (resting and impact) and one body
// step (in flight, resting on a face, asleep), on the handout's 2 x 6 x 2, 2 kg cuboid; and the
// cuboid-cuboid axis search on the pairs of a landing pyramid of 2 m cubes.
#include "body_state.hpp"
#include "collision/collide_cuboid_plane.hpp"
#include "collision/cuboid_separating_axis.hpp"
#include "dynamics/contact_solver.hpp"
#include "tumble/world.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace {

using namespace tumble;

constexpr Real kDt = 1.0 / 240.0;

BodyDef handoutCuboid()
{
    BodyDef def;
    def.shape.size = Vec3(2.0, 6.0, 2.0);
    def.mass = 2.0;
    return def;
}

/// Lying on its 2 x 6 face: four vertices on the plane.
Transform lyingOnFace()
{
    return Transform{Vec3(0.0, 1.0, 0.0), axisAngle(Vec3(0.0, 0.0, 1.0), 0.5 * M_PI)};
}

void detection(benchmark::State& state)
{
    const Transform pose = lyingOnFace();
    const Vec3 halfExtents(1.0, 3.0, 1.0);
    for (auto _ : state) {
        benchmark::DoNotOptimize(collideCuboidPlane(pose, halfExtents, Plane{}, 1e-4));
    }
}
BENCHMARK(detection);

void restingContactSolve(benchmark::State& state)
{
    // A warm-started resting solve of a body lying still on a face: the common case of a body
    // waiting to fall asleep.
    BodyDef def = handoutCuboid();
    def.position = lyingOnFace().position;
    def.orientation = lyingOnFace().orientation;
    const Body start = makeBody(def);
    ContactManifold contacts =
        collideCuboidPlane(lyingOnFace(), Vec3(1.0, 3.0, 1.0), Plane{}, 1e-4);
    Body body = start;
    WarmStartCache warmStart{};
    (void)solveRestingContact(body, contacts, Vec3(0.0, -9.81 * kDt, 0.0), kDt, {}, warmStart);
    warmStart = makeWarmStart(contacts, kDt);
    for (auto _ : state) {
        body = start;
        benchmark::DoNotOptimize(
            solveRestingContact(body, contacts, Vec3(0.0, -9.81 * kDt, 0.0), kDt, {}, warmStart));
    }
}
BENCHMARK(restingContactSolve);

void impactSolve(benchmark::State& state)
{
    // Landing on an edge (two vertices) at 5 m/s with spin: restitution, friction and the energy
    // check of (5.6).
    BodyDef def = handoutCuboid();
    def.orientation = axisAngle(Vec3(0.0, 0.0, 1.0), 0.25 * M_PI);
    def.position = Vec3(0.0, 2.0 * std::sqrt(2.0), 0.0);
    def.linearVelocity = Vec3(1.0, -5.0, 0.5);
    def.angularVelocity = Vec3(0.3, 0.2, 1.0);
    const Body start = makeBody(def);
    const ContactManifold manifold = collideCuboidPlane(
        {start.position, start.orientation}, start.shape.halfExtents(), Plane{}, 1e-4);
    for (auto _ : state) {
        Body body = start;
        ContactManifold contacts = manifold;
        benchmark::DoNotOptimize(resolveImpact(body, contacts, {}));
    }
}
BENCHMARK(impactSolve);

void bodyStepInFlight(benchmark::State& state)
{
    World world;
    world.setGround(Plane{});
    BodyDef def = handoutCuboid();
    def.position = Vec3(0.0, 1e5, 0.0);
    def.angularVelocity = Vec3(1.0, 0.5, 2.0);
    const BodyId id = world.createBody(def);
    for (auto _ : state) {
        world.step(kDt);
        if (world.body(id).position.y < 1e4) {
            world.setTransform(id, def.position, world.body(id).orientation);
        }
    }
}
BENCHMARK(bodyStepInFlight);

void bodyStepResting(benchmark::State& state)
{
    // Sleep off, so every step detects, solves the four-point resting contact and integrates.
    World world(WorldSettings{.allowSleep = false});
    world.setGround(Plane{});
    BodyDef def = handoutCuboid();
    def.position = lyingOnFace().position;
    def.orientation = lyingOnFace().orientation;
    world.createBody(def);
    for (auto _ : state) {
        world.step(kDt);
    }
}
BENCHMARK(bodyStepResting);

void bodyStepAsleep(benchmark::State& state)
{
    World world;
    world.setGround(Plane{});
    BodyDef def = handoutCuboid();
    def.position = lyingOnFace().position;
    def.orientation = lyingOnFace().orientation;
    const BodyId id = world.createBody(def);
    while (!world.body(id).asleep) {
        world.step(kDt);
    }
    for (auto _ : state) {
        world.step(kDt);
    }
}
BENCHMARK(bodyStepAsleep);

/// Pairs of 2 m cubes as a pyramid's landing meets them, each turned up to 0.05 rad about a
/// random axis: every other pair stacked (B 2 +- 0.02 m above A, up to 1 m aside, as on the
/// pyramid's odd layers), the rest side by side 2 +- 0.02 m apart along x or z.
std::vector<std::pair<CuboidFrame, CuboidFrame>> landingPyramidPairs(int count)
{
    std::mt19937 random(1240);
    std::uniform_real_distribution<Real> unit(-1.0, 1.0);
    std::uniform_real_distribution<Real> tilt(0.0, 0.05);
    // one draw per statement: the order of a call's arguments is unspecified
    const auto draw = [&] {
        const Real x = unit(random);
        const Real y = unit(random);
        return Vec3(x, y, unit(random));
    };
    const auto tilted = [&] {
        const Vec3 axis = glm::normalize(draw());
        return axisAngle(axis, tilt(random));
    };
    std::vector<std::pair<CuboidFrame, CuboidFrame>> pairs;
    for (int n = 0; n < count; ++n) {
        const Vec3 centreA = Vec3(15.0, 10.0, 15.0) * draw() + Vec3(0.0, 11.0, 0.0);
        const Vec3 aside = draw();
        const Real gap = 0.02 * aside.y;
        Vec3 offset(2.0 + gap, 0.05 * aside.x, 0.05 * aside.z);
        if (n % 2 == 0) {
            offset = Vec3(aside.x, 2.0 + gap, aside.z);
        } else if (n % 4 == 3) {
            offset = Vec3(offset.z, offset.y, offset.x);
        }
        const Quat orientationA = tilted();
        const Quat orientationB = tilted();
        pairs.emplace_back(cuboidFrame({centreA, orientationA}, Vec3(1.0)),
                           cuboidFrame({centreA + offset, orientationB}, Vec3(1.0)));
    }
    return pairs;
}

void cuboidAxisSearch(benchmark::State& state)
{
    // One fresh search (9.1)-(9.5) per iteration, cycling over 1024 pairs.
    const std::vector<std::pair<CuboidFrame, CuboidFrame>> pairs = landingPyramidPairs(1024);
    std::size_t next = 0;
    for (auto _ : state) {
        const auto& [a, b] = pairs[next];
        benchmark::DoNotOptimize(searchContactAxis(a, b, 0.02));
        next = (next + 1) % pairs.size();
    }
}
BENCHMARK(cuboidAxisSearch);

} // namespace

BENCHMARK_MAIN();
