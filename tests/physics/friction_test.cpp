// Coulomb friction against closed-form answers: sliding distance v0^2 / (2 mu g), isotropy of the
// cone, and the handout's realistic stop at elasticity 0.6 (docs/physics/06-friction.md, 07-rest.md).
#include "tumble/world.hpp"

#include "support/glm_printers.hpp"
#include "support/test_world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace tumble {
namespace {

using testing::handoutCuboid;
using testing::totalEnergy;

constexpr Real kGravity = 9.81;

/// Slides a face-down cube from rest height with horizontal velocity v0 along `direction` until
/// it stops; returns the distance travelled.
Real slidingDistance(Real speed, Real friction, Real directionAngle, Real dt, Real* stopTime = nullptr)
{
    World world = testing::worldWithGround();
    const Vec3 velocity = speed * Vec3(std::cos(directionAngle), 0, std::sin(directionAngle));
    const BodyId id = world.createBody(BodyDef{.mass = 2.0,
                                               .position = Vec3(0, 1, 0),
                                               .linearVelocity = velocity,
                                               .material = {.restitution = 0.0, .friction = friction}});
    Real stopped = -1.0;
    testing::simulate(world, 2.0 * speed / (friction * kGravity) + 1.0, dt, [&](const World& w) {
        if (stopped < 0.0 && glm::length(w.body(id).linearVelocity) < 1e-6) {
            stopped = w.time();
        }
    });
    if (stopTime != nullptr) {
        *stopTime = stopped;
    }
    const Vec3 travelled = world.body(id).position - Vec3(0, 1, 0);
    EXPECT_NEAR(travelled.y, 0.0, 1e-9);
    return glm::length(travelled);
}

struct SlideCase {
    Real speed;
    Real friction;
    Real dt;
};

void PrintTo(const SlideCase& c, std::ostream* os)
{
    *os << "v0=" << c.speed << " mu=" << c.friction << " dt=1/" << std::lround(1.0 / c.dt);
}

class Sliding : public ::testing::TestWithParam<SlideCase> {};

TEST_P(Sliding, StopsAfterTheClosedFormDistanceAndTime)
{
    // Constant deceleration mu g: distance v0^2 / (2 mu g), time v0 / (mu g) (06-friction.md, (6.5)).
    const SlideCase& c = GetParam();
    Real stopTime = 0.0;
    const Real distance = slidingDistance(c.speed, c.friction, 0.3, c.dt, &stopTime);
    const Real expected = c.speed * c.speed / (2 * c.friction * kGravity);
    EXPECT_NEAR(distance, expected, 1e-3 * expected);
    // The velocity reaches zero within the step in which the closed-form stop falls.
    EXPECT_NEAR(stopTime, c.speed / (c.friction * kGravity), c.dt);
}

INSTANTIATE_TEST_SUITE_P(
    SpeedsAndCoefficients, Sliding,
    ::testing::Values(SlideCase{4.0, 0.5, 1.0 / 240.0}, SlideCase{2.0, 0.3, 1.0 / 240.0},
                      SlideCase{6.0, 0.8, 1.0 / 240.0}, SlideCase{4.0, 0.5, 1.0 / 60.0},
                      SlideCase{4.0, 0.5, 1.0 / 960.0}));

TEST(Sliding, DistanceDoesNotDependOnTheDirectionOfThePush)
{
    // A friction pyramid would stop a push along a diagonal sooner or later than one along an
    // axis; the cone does not.
    std::vector<Real> distances;
    for (int k = 0; k < 8; ++k) {
        distances.push_back(slidingDistance(3.0, 0.6, k * std::numbers::pi / 4.0 + 0.1, 1.0 / 240.0));
    }
    const auto [shortest, longest] = std::minmax_element(distances.begin(), distances.end());
    EXPECT_LT((*longest - *shortest) / *shortest, 5e-3);
}

TEST(Sliding, StaticFrictionHoldsABodyOnASlopeThatKineticFrictionCouldNot)
{
    // Gravity tilted by 25 degrees is a 25-degree slope: tan 25 = 0.466. Static 0.5 holds the
    // resting cube; with static = kinetic = 0.4 it slides down with a = g (sin - 0.4 cos).
    const Real slope = glm::radians(25.0);
    const Vec3 gravity = kGravity * Vec3(std::sin(slope), -std::cos(slope), 0);
    for (const Real staticFriction : {0.5, 0.4}) {
        World world = testing::worldWithGround(WorldSettings{.gravity = gravity});
        const BodyId id = world.createBody(BodyDef{
            .position = Vec3(0, 1, 0),
            .material = {.restitution = 0.0, .friction = 0.4, .staticFriction = staticFriction}});
        testing::simulate(world, 1.0, 1.0 / 240.0);
        const Real expected =
            staticFriction > std::tan(slope)
                ? 0.0
                : 0.5 * kGravity * (std::sin(slope) - 0.4 * std::cos(slope)) * 1.0;
        EXPECT_NEAR(world.body(id).position.x, expected, 1e-3 + 1e-2 * expected) << staticFriction;
    }
}

struct TumbleCase {
    Vec3 velocity;
    Vec3 angularVelocity;
    Real dt;
};

void PrintTo(const TumbleCase& c, std::ostream* os)
{
    *os << "v=" << ::testing::PrintToString(c.velocity)
        << " w=" << ::testing::PrintToString(c.angularVelocity) << " dt=1/" << std::lround(1.0 / c.dt);
}

class RealisticStop : public ::testing::TestWithParam<TumbleCase> {};

TEST_P(RealisticStop, TumblingCuboidComesToRestOnOneFaceWithoutGainingEnergy)
{
    // Handout part 3 task 4: elasticity 0.6, friction 0.5, a tumbling start from 5 m.
    const TumbleCase& c = GetParam();
    World world = testing::worldWithGround();
    BodyDef def = handoutCuboid(2.0);
    def.position = Vec3(0, 5, 0);
    def.linearVelocity = c.velocity;
    def.angularVelocity = c.angularVelocity;
    def.material = {.restitution = 0.6, .friction = 0.5};
    const BodyId id = world.createBody(def);
    const Body& body = world.body(id);

    Real firstImpact = -1.0;
    Real slowSince = -1.0;
    Real deepest = 0.0;
    Real energyBefore = totalEnergy(world, id);
    for (long step = 0; step < std::lround(12.0 / c.dt); ++step) {
        world.step(c.dt);
        const Real energy = totalEnergy(world, id);
        for (const CollisionEvent& event : world.collisions()) {
            firstImpact = firstImpact < 0.0 ? event.time : firstImpact;
            EXPECT_LE(event.kineticEnergyAfter, event.kineticEnergyBefore * (1 + 1e-12));
        }
        if (!world.collisions().empty()) {
            EXPECT_LE(energy, energyBefore + 1e-9 * std::abs(energyBefore)) << "at t = " << world.time();
        }
        energyBefore = energy;
        deepest = std::max(deepest, world.contactsOf(id).maxPenetration());
        const bool slow = glm::length(body.linearVelocity) < 1e-3 &&
                          glm::length(body.angularVelocity) < 1e-3;
        slowSince = slow ? (slowSince < 0.0 ? world.time() : slowSince) : -1.0;
    }
    ASSERT_GE(firstImpact, 0.0);
    ASSERT_GE(slowSince, 0.0) << "never came to rest";
    EXPECT_LT(slowSince - firstImpact, 6.0);
    EXPECT_LT(deepest, 1e-3);
    EXPECT_EQ(world.contactsOf(id).feature(), ContactFeature::Face);
}

INSTANTIATE_TEST_SUITE_P(
    Starts, RealisticStop,
    ::testing::Values(TumbleCase{Vec3(1, 0, 0.5), Vec3(1.0, 0.5, 2.0), 1.0 / 240.0},
                      TumbleCase{Vec3(1, 0, 0.5), Vec3(1.0, 0.5, 2.0), 1.0 / 120.0},
                      TumbleCase{Vec3(1, 0, 0.5), Vec3(1.0, 0.5, 2.0), 1.0 / 960.0},
                      TumbleCase{Vec3(0), Vec3(0.1, 0.1, 0.1), 1.0 / 240.0},
                      TumbleCase{Vec3(-2, 1, 0), Vec3(0, 3, -1), 1.0 / 240.0},
                      TumbleCase{Vec3(0.5, -2, 2), Vec3(-2, 1, 4), 1.0 / 240.0}));

} // namespace
} // namespace tumble
