// Inverse inertia kept consistent with mass, size and orientation ("update on change", handout
// part 2 task 1), and impulses at a point (docs/physics/01-inertia.md, 03-impulses.md).
#include "tumble/world.hpp"

#include "support/glm_printers.hpp"
#include "support/test_world.hpp"

#include <gtest/gtest.h>

namespace tumble {
namespace {

using testing::handoutCuboid;
using testing::kExact;
using testing::kSixDecimals;
using testing::near;

Mat3 diagonal(const Vec3& d) { return Mat3(Vec3(d.x, 0, 0), Vec3(0, d.y, 0), Vec3(0, 0, d.z)); }

TEST(Body, InverseInertiaIsComputedAtCreation)
{
    World world;
    const BodyId id = world.createBody(handoutCuboid(2.0));
    EXPECT_TRUE(near(world.body(id).invInertiaWorld, diagonal(Vec3(0.15, 0.75, 0.15)), kExact));
}

TEST(Body, ChangingMassRecomputesInverseInertia)
{
    World world;
    const BodyId id = world.createBody(handoutCuboid(2.0));
    world.setMass(id, 1.0);
    EXPECT_DOUBLE_EQ(world.body(id).invMass, 1.0);
    EXPECT_TRUE(near(world.body(id).invInertiaBody, Vec3(0.3, 1.5, 0.3), kExact));
    EXPECT_TRUE(near(world.body(id).invInertiaWorld, diagonal(Vec3(0.3, 1.5, 0.3)), kExact));
}

TEST(Body, ChangingSizeRecomputesInverseInertia)
{
    World world;
    const BodyId id = world.createBody(BodyDef{.mass = 2.0}); // the 2x2x2 cube: I = 2/12 * 8
    EXPECT_TRUE(near(world.body(id).invInertiaBody, Vec3(0.75), kExact));
    world.setSize(id, Vec3(2, 6, 2));
    EXPECT_TRUE(near(world.body(id).invInertiaBody, Vec3(0.15, 0.75, 0.15), kExact));
}

TEST(Body, RotatedThirtyDegreesAboutZHasTheWorldInverseInertiaOfTheIssue)
{
    // R diag(0.15, 0.75, 0.15) R^T with c = cos 30, s = sin 30:
    // xx = 0.15 c^2 + 0.75 s^2 = 0.3, yy = 0.15 s^2 + 0.75 c^2 = 0.6, xy = (0.15 - 0.75) c s.
    World world;
    BodyDef def = handoutCuboid(2.0);
    def.orientation = axisAngle(Vec3(0, 0, 1), glm::radians(30.0));
    const BodyId id = world.createBody(def);
    const Mat3 expected(Vec3(0.3, -0.259808, 0), Vec3(-0.259808, 0.6, 0), Vec3(0, 0, 0.15));
    EXPECT_TRUE(near(world.body(id).invInertiaWorld, expected, kSixDecimals));

    world.setTransform(id, Vec3(0.0), Quat(1, 0, 0, 0));
    EXPECT_TRUE(near(world.body(id).invInertiaWorld, diagonal(Vec3(0.15, 0.75, 0.15)), kExact));
}

TEST(Body, WorldInverseInertiaFollowsTheOrientationWhileSpinning)
{
    World world(WorldSettings{.gravity = Vec3(0.0)});
    BodyDef def = handoutCuboid(2.0);
    def.angularVelocity = Vec3(0.3, -1.1, 0.7);
    const BodyId id = world.createBody(def);
    for (int i = 0; i < 500; ++i) {
        world.step(1.0 / 240.0);
    }
    const Body& body = world.body(id);
    const Mat3 rotation = glm::mat3_cast(body.orientation);
    const Mat3 expected = rotation * diagonal(body.invInertiaBody) * glm::transpose(rotation);
    EXPECT_TRUE(near(body.invInertiaWorld, expected, kExact));
    // And it is the inverse of the world inertia.
    EXPECT_TRUE(near(body.invInertiaWorld * body.inertiaWorld(), Mat3(1.0), kExact));
}

TEST(Body, ImpulseAtAPointChangesMomentumByJAndAngularMomentumByRCrossJ)
{
    World world(WorldSettings{.gravity = Vec3(0.0)});
    BodyDef def = handoutCuboid(2.0);
    def.orientation = axisAngle(glm::normalize(Vec3(1, 2, 3)), 0.7);
    def.angularVelocity = Vec3(0.1, 0.2, -0.3);
    const BodyId id = world.createBody(def);
    const Body& body = world.body(id);
    const Vec3 momentumBefore = body.linearMomentum();
    const Vec3 angularMomentumBefore = body.angularMomentum();
    const Vec3 impulse(-4.0, 1.5, 0.25);
    const Vec3 offset(0.3, -1.0, 0.5);
    world.applyImpulse(id, impulse, body.position + offset);
    EXPECT_TRUE(near(body.linearMomentum() - momentumBefore, impulse, kExact));
    EXPECT_TRUE(near(body.angularMomentum() - angularMomentumBefore, glm::cross(offset, impulse), kExact));
}

TEST(Body, PartThreeTaskOneImpulseStopsTheBodyAndSpinsItClockwise)
{
    // m = 2, v = (2, 0, 0): J = (-4, 0, 0) at r = (0, -1, 0) gives dv = -2 x and
    // dw = I^-1 (r x J) = diag(0.15, 0.75, 0.15) (0, 0, -4) = (0, 0, -0.6).
    World world(WorldSettings{.gravity = Vec3(0.0)});
    BodyDef def = handoutCuboid(2.0);
    def.linearVelocity = Vec3(2, 0, 0);
    const BodyId id = world.createBody(def);
    for (int i = 0; i < 480; ++i) {
        world.step(1.0 / 240.0);
    }
    const Body& body = world.body(id);
    EXPECT_NEAR(body.position.x, 4.0, 1e-12);
    world.applyImpulse(id, Vec3(-4, 0, 0), body.position + Vec3(0, -1, 0));
    EXPECT_LT(glm::length(body.linearVelocity), kExact);
    EXPECT_TRUE(near(body.angularVelocity, Vec3(0, 0, -0.6), kExact));
    EXPECT_LT(body.angularVelocity.z, 0.0); // clockwise seen from +z
}

} // namespace
} // namespace tumble
