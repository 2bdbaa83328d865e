// The soft step's warm start (docs/physics/12-soft-step.md, (12.5)): each contact's impulses kept
// by its owner and found again the next step by the points' feature keys, else by where the
// points lie in the owner's frame (11.6), however far the owner moved and turned in between.
#include "step/soft_warm_start.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <vector>

namespace tumble {
namespace {

constexpr Real kTolerance = 1e-3;

/// One dynamic body (slot 0, solver body 0) resting on the ground through one contact of
/// `points` points it owns.
struct Scene {
    CoupledIsland island;
    std::vector<BodySlot> slots{1};
    IslandContact contact;

    explicit Scene(int points)
    {
        island.bodies = {0};
        slots[0].alive = true;
        slots[0].body.position = Vec3(1.0, 2.0, 3.0);
        slots[0].body.orientation = glm::angleAxis(0.3, glm::normalize(Vec3(1.0, 1.0, 0.0)));
        contact.solverA = 1;
        contact.solverB = 0;
        contact.owner = 0;
        contact.ownerKey = kGroundSide;
        contact.manifold.pointCount = points;
        for (int k = 0; k < points; ++k) {
            contact.manifold.points[k].position = slots[0].body.position + Vec3(k, -0.5, 0.25 * k);
            contact.manifold.points[k].id = 10 + static_cast<std::uint32_t>(k);
        }
    }

    /// Keeps the contact with normal impulses 1, 2, 3, ... and the given friction and twist.
    void store()
    {
        SoftContactResult result;
        result.pointCount = contact.manifold.pointCount;
        for (int k = 0; k < result.pointCount; ++k) {
            result.normalImpulses[k] = 1.0 + k;
        }
        result.frictionImpulse = Vec3(0.5, 0.0, -0.25);
        result.twistImpulse = 0.125;
        const std::vector<IslandContact> contacts{contact};
        const std::vector<SoftContactResult> results{result};
        const std::vector<std::uint32_t> resultOf{0};
        storeSoftWarmStart(island, slots, contacts, results, resultOf, 1);
    }

    /// Moves and turns the body, and the contact's points with it (x' = p' + R' R^T (x - p)).
    void carry(const Vec3& shift, const Quat& turn)
    {
        Body& body = slots[0].body;
        const Vec3 before = body.position;
        const Quat relative = turn;
        body.position += shift;
        body.orientation = glm::normalize(turn * body.orientation);
        for (int k = 0; k < contact.manifold.pointCount; ++k) {
            Vec3& x = contact.manifold.points[k].position;
            x = body.position + relative * (x - before);
        }
    }
};

TEST(SoftWarmStart, APointKeepsItsImpulseByItsFeatureKey)
{
    Scene scene(3);
    scene.store();
    // the points move far (1 m) but keep their features: each takes its own impulse back
    for (int k = 0; k < 3; ++k) {
        scene.contact.manifold.points[k].position += Vec3(0.0, 1.0, 0.0);
    }
    const KeptImpulses kept = keptImpulsesOf(scene.island, scene.slots, scene.contact, kTolerance);
    ASSERT_TRUE(kept.found);
    EXPECT_EQ(kept.normalImpulses[0], 1.0);
    EXPECT_EQ(kept.normalImpulses[1], 2.0);
    EXPECT_EQ(kept.normalImpulses[2], 3.0);
    EXPECT_EQ(kept.frictionImpulse, Vec3(0.5, 0.0, -0.25));
    EXPECT_EQ(kept.twistImpulse, 0.125);
}

TEST(SoftWarmStart, ARenamedPointIsFoundWhereItLiesOnItsOwnerAfterTheOwnerMoved)
{
    Scene scene(3);
    scene.store();
    // the owner moves 2 m and turns 0.7 rad before the next step: the points ride with it
    scene.carry(Vec3(2.0, -1.0, 0.5), glm::angleAxis(0.7, Vec3(0.0, 0.0, 1.0)));
    // points 0 and 2 got new feature keys; point 2 also lies 9 tolerances from where it was on
    // the body (within the ten allowed), point 0 exactly where it was
    scene.contact.manifold.points[0].id = 90;
    scene.contact.manifold.points[2].id = 92;
    scene.contact.manifold.points[2].position += Vec3(9.0 * kTolerance, 0.0, 0.0);
    KeptImpulses kept = keptImpulsesOf(scene.island, scene.slots, scene.contact, kTolerance);
    ASSERT_TRUE(kept.found);
    EXPECT_EQ(kept.normalImpulses[0], 1.0);
    EXPECT_EQ(kept.normalImpulses[1], 2.0);
    EXPECT_EQ(kept.normalImpulses[2], 3.0);
    // 11 tolerances away, it starts from nothing
    scene.contact.manifold.points[2].position += Vec3(2.0 * kTolerance, 0.0, 0.0);
    kept = keptImpulsesOf(scene.island, scene.slots, scene.contact, kTolerance);
    EXPECT_EQ(kept.normalImpulses[0], 1.0);
    EXPECT_EQ(kept.normalImpulses[2], 0.0);
}

TEST(SoftWarmStart, AContactTheOwnerDidNotKeepStartsFromNothing)
{
    Scene scene(2);
    scene.store();
    scene.contact.ownerKey = kPlaneSide;
    const KeptImpulses kept = keptImpulsesOf(scene.island, scene.slots, scene.contact, kTolerance);
    EXPECT_FALSE(kept.found);
    EXPECT_EQ(kept.normalImpulses[0], 0.0);
    EXPECT_EQ(kept.twistImpulse, 0.0);
}

} // namespace
} // namespace tumble
