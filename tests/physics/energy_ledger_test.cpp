// The energy ledger: every change of a body's energy is booked under one heading, and the books
// balance (docs/physics/08-energy-ledger.md).
#include "tumble/world.hpp"

#include "support/test_world.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble {
namespace {

using testing::handoutCuboid;

/// kinetic + potential + removed - added - initial, relative to the energy scale of the run.
Real imbalance(const World& world, BodyId id, Real scale)
{
    const Body& body = world.body(id);
    const EnergyLedger& ledger = body.ledger;
    return std::abs(ledger.imbalance(world.energyOf(body))) / scale;
}

TEST(EnergyLedger, BalancesAtEveryStepOfATumblingThrowAndTheSolverNeverAddsEnergy)
{
    World world = testing::worldWithGround();
    BodyDef def = handoutCuboid(2.0);
    def.position = Vec3(0, 5, 0);
    def.linearVelocity = Vec3(1, 0, 0.5);
    def.angularVelocity = Vec3(1.0, 0.5, 2.0);
    const BodyId id = world.createBody(def);
    const Real scale = std::abs(world.energyOf(world.body(id)));
    testing::simulate(world, 10.0, 1.0 / 240.0, [&](const World& w) {
        ASSERT_LT(imbalance(w, id, scale), 1e-9) << "t = " << w.time();
        ASSERT_LE(w.body(id).ledger.impactWorkLastStep, 1e-12 * scale) << "t = " << w.time();
    });
    const EnergyLedger& ledger = world.body(id).ledger;
    // It came to rest: the kinetic energy at the start went to restitution, friction and rest.
    EXPECT_GT(ledger.removedByNormal, 0.0);
    EXPECT_GT(ledger.removedByFriction, 0.0);
    // The integrator may lose a little (the normal position update in pushed sub-steps is
    // semi-implicit, docs/physics/02-integration.md, (2.2a)) but never gains.
    EXPECT_GT(ledger.removedByIntegration, -1e-6 * scale);
    EXPECT_LT(ledger.removedByIntegration, 1e-3 * scale);
}

TEST(EnergyLedger, FaceDownImpactRemovesOneMinusESquaredOfTheImpactEnergy)
{
    // Impact at speed v: restitution takes m v^2 (1 - e^2) / 2.
    World world = testing::worldWithGround();
    const BodyId id = world.createBody(BodyDef{.mass = 3.0, .position = Vec3(0, 2, 0),
                                               .material = {.restitution = 0.6, .friction = 0.5}});
    Real removedAtImpact = -1.0;
    testing::simulate(world, 1.0, 1.0 / 240.0, [&](const World& w) {
        if (removedAtImpact < 0.0 && !w.collisions().empty()) {
            removedAtImpact = w.body(id).ledger.removedByNormal;
        }
    });
    const Real impactSpeedSquared = 2.0 * 9.81 * 1.0;
    EXPECT_NEAR(removedAtImpact, 0.5 * 3.0 * impactSpeedSquared * (1 - 0.36),
                1e-6 * impactSpeedSquared);
    EXPECT_NEAR(world.body(id).ledger.removedByFriction, 0.0, 1e-12);
}

TEST(EnergyLedger, SlidingToRestBooksTheKineticEnergyToFriction)
{
    World world = testing::worldWithGround();
    const BodyId id = world.createBody(BodyDef{.mass = 2.0, .position = Vec3(0, 1, 0),
                                               .linearVelocity = Vec3(3, 0, 0),
                                               .material = {.restitution = 0.0, .friction = 0.5}});
    testing::simulate(world, 2.0, 1.0 / 240.0);
    const EnergyLedger& ledger = world.body(id).ledger;
    EXPECT_NEAR(ledger.removedByFriction, 0.5 * 2.0 * 9.0, 1e-9);
    EXPECT_NEAR(ledger.removedByNormal, 0.0, 1e-9);
}

TEST(EnergyLedger, ImpulsesAndEditsAreBookedAsAdded)
{
    World world(WorldSettings{.gravity = Vec3(0.0)});
    const BodyId id = world.createBody(handoutCuboid(2.0));
    world.applyImpulse(id, Vec3(-4, 0, 0), Vec3(0, -1, 0));
    // v = (-2, 0, 0), w = (0, 0, -0.6): KE = m v^2 / 2 + Iz w^2 / 2 = 4 + 0.5 (20/3) 0.36.
    EXPECT_NEAR(world.body(id).ledger.added, 4.0 + 0.5 * (20.0 / 3.0) * 0.36, 1e-12);
    world.setLinearVelocity(id, Vec3(0.0));
    world.setGravity(Vec3(0, -9.81, 0));
    world.setTransform(id, Vec3(0, 2, 0), Quat(1, 0, 0, 0));
    EXPECT_NEAR(imbalance(world, id, 1.0), 0.0, 1e-12);
}

TEST(EnergyLedger, ElasticFrictionlessBouncesRemoveNothing)
{
    World world = testing::worldWithGround();
    BodyDef def = handoutCuboid(2.0);
    def.position = Vec3(0, 5, 0);
    def.angularVelocity = Vec3(0, 0, 0.5);
    def.material = {.restitution = 1.0, .friction = 0.0};
    const BodyId id = world.createBody(def);
    testing::simulate(world, 10.0, 1.0 / 240.0);
    const EnergyLedger& ledger = world.body(id).ledger;
    const Real scale = std::abs(ledger.initial);
    EXPECT_LT(std::abs(ledger.removedByNormal), 1e-9 * scale);
    EXPECT_EQ(ledger.removedByFriction, 0.0);
    EXPECT_LT(std::abs(ledger.removed()), 1e-6 * scale);
}

TEST(EnergyLedger, AHeadOnImpactOfTwoCubesBooksWhatTheStruckCubeGainsAsExchanged)
{
    // Equal masses m, e = 0.5, B at v on A at rest, face on, no gravity: A leaves at (1 + e) v / 2
    // and B at (1 - e) v / 2. The pair loses m v^2 (1 - e^2) / 4 (8.2), all of it booked on B,
    // which alone moved before (8.4); A's kinetic energy came from B, so A books it as exchanged
    // and B the same amount with the opposite sign (docs/physics/11-island-solver.md, Energy).
    World world(WorldSettings{.gravity = Vec3(0.0)});
    const Real m = 2.0;
    const Real v = 2.0;
    const Real e = 0.5;
    const Material material{.restitution = e, .friction = 0.5};
    const BodyId struck =
        world.createBody(BodyDef{.mass = m, .position = Vec3(0, 5, 0), .material = material});
    const BodyId striker = world.createBody(BodyDef{.mass = m, .position = Vec3(-3, 5, 0),
                                                    .linearVelocity = Vec3(v, 0, 0),
                                                    .material = material});
    testing::simulate(world, 1.0, 1.0 / 240.0);
    const Real scale = 0.5 * m * v * v;
    EXPECT_NEAR(world.body(struck).linearVelocity.x, 0.5 * (1 + e) * v, 1e-9);
    EXPECT_NEAR(world.body(striker).linearVelocity.x, 0.5 * (1 - e) * v, 1e-9);
    const EnergyLedger& a = world.body(struck).ledger;
    const EnergyLedger& b = world.body(striker).ledger;
    const Real gained = 0.5 * m * std::pow(0.5 * (1 + e) * v, 2);
    EXPECT_NEAR(a.exchanged, gained, 1e-9 * scale);
    EXPECT_NEAR(b.exchanged, -gained, 1e-9 * scale);
    EXPECT_NEAR(a.removedByNormal, 0.0, 1e-9 * scale);
    EXPECT_NEAR(b.removedByNormal, 0.25 * m * v * v * (1 - e * e), 1e-9 * scale);
    EXPECT_NEAR(a.removedByFriction + b.removedByFriction, 0.0, 1e-9 * scale);
    EXPECT_LT(imbalance(world, struck, scale), 1e-9);
    EXPECT_LT(imbalance(world, striker, scale), 1e-9);
}

TEST(EnergyLedger, ContactRecordsDescribeEachSolve)
{
    World world = testing::worldWithGround(WorldSettings{.recordContacts = true});
    world.createBody(BodyDef{.position = Vec3(0, 1.5, 0), .material = {.restitution = 0.5}});
    bool sawImpact = false;
    testing::simulate(world, 0.5, 1.0 / 240.0, [&](const World& w) {
        for (const ContactRecord& record : w.contactRecords()) {
            if (record.phase != ContactPhase::Impact || sawImpact) {
                continue;
            }
            sawImpact = true;
            ASSERT_EQ(record.manifold.pointCount, 4);
            for (int i = 0; i < 4; ++i) {
                const ContactPoint& point = record.manifold.points[i];
                EXPECT_EQ(point.restitution, RestitutionState::Applied);
                EXPECT_NEAR(point.velocityAfter.y, -0.5 * point.velocityBefore.y, 1e-9);
                EXPECT_FALSE(point.sliding);
            }
        }
    });
    EXPECT_TRUE(sawImpact);
}

} // namespace
} // namespace tumble
