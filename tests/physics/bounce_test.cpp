// Bounces against closed-form answers: rebound ratio = restitution, apex heights h e^(2k), impact
// times, and energy conservation for a perfectly elastic tumbling cuboid
// (docs/physics/05-normal-impulse.md, 04-detection.md).
#include "tumble/world.hpp"

#include "support/glm_printers.hpp"
#include "support/test_world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <tuple>
#include <vector>

namespace tumble {
namespace {

using testing::handoutCuboid;
using testing::totalEnergy;

constexpr Real kGravity = 9.81;

struct DropCase {
    Real restitution;
    Real dt;
    ContactResponse response;
};

void PrintTo(const DropCase& c, std::ostream* os)
{
    *os << "e=" << c.restitution << " dt=1/" << std::lround(1.0 / c.dt)
        << (c.response == ContactResponse::Average ? " average" : " sequential");
}

class FaceDownDrop : public ::testing::TestWithParam<DropCase> {};

TEST_P(FaceDownDrop, ReboundSpeedOverImpactSpeedIsTheRestitution)
{
    const DropCase& c = GetParam();
    World world = testing::worldWithGround(WorldSettings{.response = c.response});
    const BodyId id = world.createBody(BodyDef{
        .mass = 1.5, .position = Vec3(0, 3, 0), .material = {.restitution = c.restitution, .friction = 0.5}});
    bool measured = false;
    testing::simulate(world, 1.5, c.dt, [&](const World& w) {
        if (measured || w.collisions().empty()) {
            return;
        }
        measured = true;
        const CollisionEvent& impact = w.collisions().front();
        EXPECT_EQ(impact.manifold.feature(), ContactFeature::Face);
        // The step may go on after the impact in free flight; undo that much gravity.
        const Real rebound = w.body(id).linearVelocity.y + kGravity * (w.time() - impact.time);
        EXPECT_NEAR(rebound / impact.approachSpeed, c.restitution, 5e-3 * c.restitution);
    });
    EXPECT_TRUE(measured);
}

std::vector<DropCase> dropCases()
{
    std::vector<DropCase> cases;
    for (const ContactResponse response : {ContactResponse::Sequential, ContactResponse::Average}) {
        for (const Real restitution : {0.3, 0.6, 0.9, 1.0}) {
            for (const Real dt : {1.0 / 120.0, 1.0 / 240.0, 1.0 / 480.0}) {
                cases.push_back({restitution, dt, response});
            }
        }
    }
    return cases;
}

INSTANTIATE_TEST_SUITE_P(RestitutionsStepsResponses, FaceDownDrop, ::testing::ValuesIn(dropCases()));

class BounceSequence : public ::testing::TestWithParam<Real> {};

TEST_P(BounceSequence, ApexHeightsAndImpactTimesFollowTheGeometricSeries)
{
    // Dropped from clearance h: impact k at t_k = T (1 + 2 e + ... + 2 e^(k-1)) with
    // T = sqrt(2 h / g), and apex k (after impact k) at clearance h e^(2k)
    // (docs/physics/05-normal-impulse.md, (5.8)).
    const Real dt = GetParam();
    const Real restitution = 0.8;
    const Real clearance = 2.0;
    World world = testing::worldWithGround();
    const BodyId id = world.createBody(BodyDef{
        .position = Vec3(0, 1 + clearance, 0), .material = {.restitution = restitution, .friction = 0.3}});
    std::vector<Real> impactTimes;
    std::vector<Real> apexClearances;
    Real previousVelocity = 0.0;
    testing::simulate(world, 4.0, dt, [&](const World& w) {
        for (const CollisionEvent& event : w.collisions()) {
            impactTimes.push_back(event.time);
        }
        const Body& body = w.body(id);
        if (previousVelocity > 0.0 && body.linearVelocity.y <= 0.0) {
            // Free flight is an exact parabola: the apex is y + v^2 / (2 g) from any point.
            const Real vy = body.linearVelocity.y;
            apexClearances.push_back(body.position.y - 1.0 + vy * vy / (2 * kGravity));
        }
        previousVelocity = body.linearVelocity.y;
    });
    const Real fallTime = std::sqrt(2 * clearance / kGravity);
    ASSERT_GE(impactTimes.size(), 3u);
    ASSERT_GE(apexClearances.size(), 3u);
    Real expectedTime = fallTime;
    for (int k = 0; k < 3; ++k) {
        // The time of impact stops within 1e-8 m of the plane (04-detection.md): ~1e-9 s here.
        EXPECT_NEAR(impactTimes[k], expectedTime, 2e-8) << "impact " << k + 1;
        expectedTime += 2 * std::pow(restitution, k + 1) * fallTime;
        EXPECT_NEAR(apexClearances[k], clearance * std::pow(restitution, 2 * (k + 1)), 5e-8)
            << "apex " << k + 1;
    }
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, BounceSequence,
                         ::testing::Values(1.0 / 60.0, 1.0 / 240.0, 1.0 / 960.0));

class ElasticSpin : public ::testing::TestWithParam<Real> {};

TEST_P(ElasticSpin, PartThreeTaskThreeCaseOneConservesEnergyAndDoesNotPenetrate)
{
    // Handout part 3 task 3, case 1: w = (0, 0, 0.5), elasticity 1, no friction, 10 s.
    const Real dt = GetParam();
    World world = testing::worldWithGround();
    BodyDef def = handoutCuboid(2.0);
    def.position = Vec3(0, 5, 0);
    def.angularVelocity = Vec3(0, 0, 0.5);
    def.material = {.restitution = 1.0, .friction = 0.0};
    const BodyId id = world.createBody(def);
    const Real energy0 = totalEnergy(world, id);
    Real largestEnergyError = 0.0;
    Real deepest = 0.0;
    int impacts = 0;
    testing::simulate(world, 10.0, dt, [&](const World& w) {
        largestEnergyError =
            std::max(largestEnergyError, std::abs(totalEnergy(w, id) / energy0 - 1.0));
        deepest = std::max(deepest, w.contactsOf(id).maxPenetration());
        impacts += static_cast<int>(w.collisions().size());
    });
    EXPECT_GE(impacts, 3);
    EXPECT_LT(largestEnergyError, 5e-3);
    EXPECT_LT(deepest, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, ElasticSpin,
                         ::testing::Values(1.0 / 60.0, 1.0 / 240.0, 1.0 / 960.0));

} // namespace
} // namespace tumble
