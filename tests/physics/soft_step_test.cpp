// The soft step (WorldSettings::solver = ContactSolver::Soft) against the closed forms of
// docs/physics/12-soft-step.md: the springs' static compression (12.2a), sliding and holding on a
// slope (6.6), restitution (12.6), momentum, and the same bits for any number of threads.
#include "tumble/state_hash.hpp"
#include "tumble/world.hpp"

#include "support/slope_world.hpp"
#include "support/test_world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace tumble {
namespace {

constexpr Real kGravity = 9.81;
constexpr Real kPi = std::numbers::pi;

WorldSettings softSettings()
{
    return WorldSettings{.solver = ContactSolver::Soft, .allowSleep = false};
}

/// A column of `count` unit cubes of mass 1 on the ground, touching face to face.
std::vector<BodyId> addColumn(World& world, int count)
{
    std::vector<BodyId> cubes;
    for (int i = 0; i < count; ++i) {
        cubes.push_back(world.createBody(
            BodyDef{.shape = Cuboid{Vec3(1.0)},
                    .position = Vec3(0.0, 0.5 + i, 0.0),
                    .material = Material{.restitution = 0.0, .friction = 0.5}}));
    }
    return cubes;
}

/// (12.2a): a point of effective mass m carrying a force F settles where its spring of
/// angular frequency omega holds it, F = m omega^2 |s|.
Real springGap(Real force, Real effectiveMass, Real hertz)
{
    const Real omega = 2.0 * kPi * hertz;
    return force / (effectiveMass * omega * omega);
}

/// The largest distance of a column's cubes from its axis.
Real offAxis(const World& world, const std::vector<BodyId>& cubes)
{
    Real largest = 0.0;
    for (const BodyId cube : cubes) {
        const Vec3& p = world.body(cube).position;
        largest = std::max(largest, std::hypot(p.x, p.z));
    }
    return largest;
}

TEST(SoftStep, AColumnSettlesOnItsSpringsAsTheirStiffnessSays)
{
    // dt = 1/60 over 4 sub-steps: contacts of 30 Hz between cubes, 60 Hz against the ground.
    // A unit cube's corner has effective mass 1 / (1/m + |r x n|^2 / I) = 1 / (1 + 0.5 * 6) =
    // 1/4 against the ground, 1/8 between two cubes; each face carries its load on 4 corners.
    World world = testing::worldWithGround(softSettings());
    const std::vector<BodyId> cubes = addColumn(world, 10);
    testing::simulate(world, 8.0, 1.0 / 60.0);
    const Real groundGap = springGap(10 * kGravity / 4.0, 0.25, 60.0);
    const Real firstGap = springGap(9 * kGravity / 4.0, 0.125, 30.0);
    const Real bottom = world.body(cubes[0]).position.y;
    const Real second = world.body(cubes[1]).position.y;
    EXPECT_NEAR(0.5 - bottom, groundGap, 0.02 * groundGap);
    EXPECT_NEAR(1.0 - (second - bottom), firstGap, 0.02 * firstGap);
    // at rest by (7.1)'s test, on its axis
    EXPECT_LT(offAxis(world, cubes), 0.01);
    for (const BodyId cube : cubes) {
        EXPECT_LT(glm::length(world.body(cube).linearVelocity), 1e-3);
    }
}

TEST(SoftStep, AColumnOfTwentyStandsOnlyOnSpringsStiffEnoughNotToBuckle)
{
    // (12.7): the column's tilts are stable while K - G is positive definite, K the interfaces'
    // rotational stiffness 4 k (1/2)^2 with k = m_eff omega^2, G the weight above each cube
    // times its lever. For 20 unit cubes that fails at 30 Hz and holds at 45 Hz and up.
    for (const Real hertz : {30.0, 60.0}) {
        WorldSettings settings = softSettings();
        settings.softContactHertz = hertz;
        World world = testing::worldWithGround(settings);
        const std::vector<BodyId> cubes = addColumn(world, 20);
        testing::simulate(world, 10.0, 1.0 / 60.0);
        if (hertz < 45.0) {
            EXPECT_GT(offAxis(world, cubes), 0.1) << hertz << " Hz";
        } else {
            EXPECT_LT(offAxis(world, cubes), 0.01) << hertz << " Hz";
        }
    }
}

using testing::Slope;

Slope makeSlope(Real degrees, Real friction)
{
    return testing::makeSlope(degrees, friction, 1.0, 1.0, softSettings());
}

TEST(SoftStep, SlidesDownASlopeAtGTimesSinMinusMuCos)
{
    // (6.6): d = g (sin t - mu cos t) T^2 / 2; the sub-steps' positions from the new velocity
    // run ahead of it by a T h / 2 (12.4), allowed twice
    const Real dt = 1.0 / 240.0;
    Slope slope = makeSlope(30.0, 0.3);
    const Vec3 start = slope.world.body(slope.box).position;
    testing::simulate(slope.world, 2.0, dt);
    const Real angle = kPi / 6.0;
    const Real a = kGravity * (std::sin(angle) - 0.3 * std::cos(angle));
    const Vec3 travel = slope.world.body(slope.box).position - start;
    EXPECT_NEAR(glm::dot(travel, slope.downhill), 0.5 * a * 4.0, a * 2.0 * dt / 4.0);
    EXPECT_LT(glm::length(travel - glm::dot(travel, slope.downhill) * slope.downhill), 1e-4);
}

TEST(SoftStep, HoldsOnASlopeWhenFrictionIsAtLeastTheTangent)
{
    // at 20 degrees tan t = 0.364: mu = 0.4 holds, mu = 0.3 slides
    Slope holds = makeSlope(20.0, 0.4);
    const Vec3 start = holds.world.body(holds.box).position;
    testing::simulate(holds.world, 2.0, 1.0 / 60.0);
    EXPECT_LT(glm::length(holds.world.body(holds.box).position - start), 1e-3);

    Slope slides = makeSlope(20.0, 0.3);
    testing::simulate(slides.world, 2.0, 1.0 / 60.0);
    EXPECT_GT(glm::dot(slides.world.body(slides.box).position - start, slides.downhill), 0.5);
}

TEST(SoftStep, ALandingOnASlopeInsideTheFrictionConeStopsItsSlide)
{
    // (6.6) for an impact: a cube falling at v onto a slope of angle t, face down, e = 0, meets
    // a normal impulse m v cos t, and friction can take m v sin t from it where tan t <= mu: a
    // rigid landing stops dead. Had the landing kept v sin t, kinetic friction would stop the
    // cube after d0 = (v sin t)^2 / (2 g (mu cos t - sin t)) = 0.42 m. The soft step's passes
    // (one each per sub-step, friction in both, (12.5)) take most of it at the landing: the
    // cube slides under a tenth of d0 at 60 Hz and under 1 % of it at 240 Hz.
    const Real speed = 3.0;
    const Real angle = kPi / 9.0;
    const Real mu = 0.5;
    const Real tangential = speed * std::sin(angle);
    const Real unstopped =
        tangential * tangential / (2.0 * kGravity * (mu * std::cos(angle) - std::sin(angle)));
    for (const auto& [dt, share] : {std::pair{1.0 / 60.0, 0.15}, std::pair{1.0 / 240.0, 0.01}}) {
        Slope slope = makeSlope(20.0, mu);
        World& world = slope.world;
        const Vec3 normal(slope.downhill.y, -slope.downhill.x, 0.0);
        world.setTransform(slope.box, world.body(slope.box).position + 0.01 * normal,
                           world.body(slope.box).orientation);
        world.setLinearVelocity(slope.box, Vec3(0.0, -speed, 0.0));
        // where it lands: its 1 cm gap along the normal closed by the vertical fall
        const Vec3 landing = world.body(slope.box).position - (0.01 / normal.y) * Vec3(0, 1, 0);
        testing::simulate(world, 1.0, dt);
        const Real slide = glm::dot(world.body(slope.box).position - landing, slope.downhill);
        EXPECT_LT(std::abs(slide), share * unstopped) << "dt " << dt;
        EXPECT_LT(glm::length(world.body(slope.box).linearVelocity), 1e-3) << "dt " << dt;
    }
}

TEST(SoftStep, BouncesBackToESquaredOfItsDropHeight)
{
    // (12.6): a cube dropped from 1 m onto a static block leaves at e times its approach speed
    // and rises e^2 as high; the approach is read at the start of the landing step, g dt slower
    World world(softSettings());
    world.createBody(BodyDef{.motion = BodyMotion::Static,
                             .shape = Cuboid{Vec3(4.0, 1.0, 4.0)},
                             .position = Vec3(0.0, -0.5, 0.0),
                             .materialGiven = false});
    const Real e = 0.5;
    const BodyId cube = world.createBody(
        BodyDef{.position = Vec3(0.0, 2.0, 0.0),
                .material = Material{.restitution = e, .friction = 0.0}});
    Real lowest = 10.0;
    Real apex = 0.0;
    testing::simulate(world, 1.5, 1.0 / 240.0, [&](const World& w) {
        const Real y = w.body(cube).position.y - 1.0;
        lowest = std::min(lowest, y);
        if (lowest < 0.01) {
            apex = std::max(apex, y);
        }
    });
    EXPECT_NEAR(lowest, 0.0, 1e-3);
    EXPECT_NEAR(apex, e * e * 1.0, 0.05 * e * e);
}

TEST(SoftStep, AHeadOnElasticCollisionSwapsVelocitiesAndKeepsMomentum)
{
    WorldSettings settings = softSettings();
    settings.gravity = Vec3(0.0);
    World world(settings);
    const Material elastic{.restitution = 1.0, .friction = 0.0};
    const BodyId left = world.createBody(BodyDef{.position = Vec3(-1.2, 0.0, 0.0),
                                                 .linearVelocity = Vec3(1.0, 0.0, 0.0),
                                                 .material = elastic});
    const BodyId right = world.createBody(BodyDef{.position = Vec3(1.2, 0.0, 0.0),
                                                  .linearVelocity = Vec3(-1.0, 0.0, 0.0),
                                                  .material = elastic});
    testing::simulate(world, 1.0, 1.0 / 60.0);
    const Vec3 vLeft = world.body(left).linearVelocity;
    const Vec3 vRight = world.body(right).linearVelocity;
    // momentum to rounding; the swap to what a few sweeps over the face's points leave (12.6)
    EXPECT_LT(glm::length(vLeft + vRight), 1e-12);
    EXPECT_NEAR(vLeft.x, -1.0, 1e-4);
    EXPECT_NEAR(vRight.x, 1.0, 1e-4);
    EXPECT_LT(glm::length(world.body(left).angularVelocity), 1e-4);
}

/// Two layers of boxes dropped onto each other, with a spin, sleeping on.
World dropPile(int threads)
{
    WorldSettings settings = softSettings();
    settings.allowSleep = true;
    settings.threads = threads;
    World world = testing::worldWithGround(settings);
    for (int i = 0; i < 12; ++i) {
        const Real x = (i % 4) * 1.1 - 1.65;
        const Real y = 0.6 + (i / 4) * 1.3;
        world.createBody(BodyDef{.shape = Cuboid{Vec3(1.0, 0.6, 0.8)},
                                 .position = Vec3(x + 0.3 * (i / 4), y, 0.05 * i),
                                 .orientation = axisAngle(Vec3(1, 0, 1), 0.1 * i),
                                 .angularVelocity = Vec3(0.0, 0.5, 0.0),
                                 .material = Material{.restitution = 0.3, .friction = 0.6}});
    }
    return world;
}

TEST(SoftStep, APileComesToRestTheSameForAnyThreadsAndItsLedgersBalance)
{
    World one = dropPile(1);
    World two = dropPile(2);
    testing::simulate(one, 6.0, 1.0 / 60.0);
    testing::simulate(two, 6.0, 1.0 / 60.0);
    EXPECT_EQ(stateHash(one), stateHash(two));
    for (const BodyId id : one.bodyIds()) {
        const Body& body = one.body(id);
        EXPECT_TRUE(body.asleep);
        const Real energy = body.kineticEnergy() + body.potentialEnergy(one.settings().gravity);
        EXPECT_NEAR(body.ledger.imbalance(energy), 0.0, 1e-9 * std::abs(body.ledger.initial));
    }
}

// (8.4), (12.8): cubes resting side by side on the ground exchange no energy, and each
// sub-step their contacts take back the speed g h gravity gave them: 1/2 m (g h)^2 a cube a
// sub-step, booked as normal work, which the warm start's impulses do.
TEST(SoftStep, CubesSideBySideExchangeNothingAndTheirContactsTakeBackGravitysSpeed)
{
    World world = testing::worldWithGround(softSettings());
    std::vector<BodyId> cubes;
    for (int i = 0; i < 3; ++i) {
        cubes.push_back(world.createBody(
            BodyDef{.shape = Cuboid{Vec3(1.0)},
                    .position = Vec3(i, 0.5, 0.0),
                    .material = Material{.restitution = 0.0, .friction = 0.5}}));
    }
    const Real dt = 1.0 / 60.0;
    const int steps = 150;
    for (int s = 0; s < steps; ++s) {
        world.step(dt);
    }
    const int substeps = world.settings().softSubsteps;
    const Real h = dt / substeps;
    const Real perCube = steps * substeps * 0.5 * (kGravity * h) * (kGravity * h);
    Real exchanged = 0.0;
    Real normal = 0.0;
    for (const BodyId cube : cubes) {
        exchanged += world.body(cube).ledger.exchanged;
        normal += world.body(cube).ledger.removedByNormal;
    }
    EXPECT_NEAR(exchanged, 0.0, 1e-9 * perCube);
    EXPECT_NEAR(normal, 3.0 * perCube, 1e-3 * perCube);
}

/// Whether every body's vertical speed after the step that woke them is far below the g dt
/// a body on no contact would have.
void expectWokenAndHeld(const World& world, const std::vector<BodyId>& bodies)
{
    for (const BodyId id : bodies) {
        EXPECT_FALSE(world.body(id).asleep);
        EXPECT_LT(std::abs(world.body(id).linearVelocity.y), 1e-2 * kGravity / 60.0);
    }
}

TEST(SoftStep, AColumnWokenFromSleepStandsOnItsContactsFromItsFirstStep)
{
    // (10.4b): while the column sleeps its pairs keep their test's answer and find no points;
    // the step that wakes it finds them, so no cube falls for a step on contacts not found
    WorldSettings settings = softSettings();
    settings.allowSleep = true;
    World world = testing::worldWithGround(settings);
    const std::vector<BodyId> column = addColumn(world, 3);
    testing::simulate(world, 2.0, 1.0 / 60.0);
    for (const BodyId cube : column) {
        ASSERT_TRUE(world.body(cube).asleep);
    }
    world.applyImpulse(column.back(), Vec3(0.05, 0.0, 0.0), world.body(column.back()).position);
    world.step(1.0 / 60.0);
    expectWokenAndHeld(world, column);
}

TEST(SoftStep, ALargeIslandWokenFromSleepOnTwoThreadsStandsOnItsContacts)
{
    // the same on an island large enough to take both threads (11.5c), whose narrow phase
    // places its contacts from the pairs' point counts
    WorldSettings settings = softSettings();
    settings.allowSleep = true;
    settings.threads = 2;
    World world = testing::worldWithGround(settings);
    std::vector<BodyId> cubes;
    for (int layer = 0; layer < 3; ++layer) {
        for (int i = 0; i < 100; ++i) {
            cubes.push_back(world.createBody(
                BodyDef{.shape = Cuboid{Vec3(1.0)},
                        .position = Vec3((i % 10) * 1.0, 0.5 + layer, (i / 10) * 1.0),
                        .material = Material{.restitution = 0.0, .friction = 0.5}}));
        }
    }
    testing::simulate(world, 2.0, 1.0 / 60.0);
    for (const BodyId cube : cubes) {
        ASSERT_TRUE(world.body(cube).asleep);
    }
    world.applyImpulse(cubes.back(), Vec3(0.05, 0.0, 0.0), world.body(cubes.back()).position);
    world.step(1.0 / 60.0);
    EXPECT_GE(world.solverStatistics().contactPoints, 1024u);
    expectWokenAndHeld(world, cubes);
}

/// Three layers of 10 x 10 cubes, each layer dropped 0.2 m onto the one below, with a twist:
/// one island of some 2 000 pairs, which takes all the threads inside its step (11.5c).
World dropLayers(int threads)
{
    WorldSettings settings = softSettings();
    settings.threads = threads;
    World world = testing::worldWithGround(settings);
    for (int layer = 0; layer < 3; ++layer) {
        for (int i = 0; i < 100; ++i) {
            const Real x = (i % 10) * 1.0 - 4.5 + 0.3 * layer;
            const Real z = (i / 10) * 1.0 - 4.5;
            world.createBody(BodyDef{.shape = Cuboid{Vec3(1.0)},
                                     .position = Vec3(x, 0.5 + 1.2 * layer, z),
                                     .orientation = axisAngle(Vec3(0, 1, 0), 0.01 * layer),
                                     .material = Material{.restitution = 0.2, .friction = 0.5}});
        }
    }
    return world;
}

TEST(SoftStep, ALargeIslandGivesTheSameBitsOnOneAndTwoThreads)
{
    World one = dropLayers(1);
    World two = dropLayers(2);
    testing::simulate(one, 1.0, 1.0 / 60.0);
    testing::simulate(two, 1.0, 1.0 / 60.0);
    EXPECT_GE(one.solverStatistics().contactPoints, 1024u);
    EXPECT_EQ(stateHash(one), stateHash(two));
}

} // namespace
} // namespace tumble
