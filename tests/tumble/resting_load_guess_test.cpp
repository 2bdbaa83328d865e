// The first guess of new resting contacts: the weight each body carries, passed down by the
// least-norm normal forces of its supporting contacts (docs/physics/11-island-solver.md, (11.13)).
#include "step/resting_load_guess.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace tumble {
namespace {

constexpr Real kGravity = 9.81;
constexpr Real kTau = 1.0 / 60;

/// An island of dynamic bodies of the given masses at the given heights.
struct Scene {
    CoupledIsland island;
    std::vector<BodySlot> slots;
    std::vector<IslandContact> contacts;
    std::vector<ContactConstraint> constraints;

    void addBody(Real mass, const Vec3& position)
    {
        island.bodies.push_back(static_cast<std::uint32_t>(slots.size()));
        BodySlot& slot = slots.emplace_back();
        slot.body.mass = mass;
        slot.body.position = position;
        slot.alive = true;
    }
    /// A contact of `points` points with normal n from solver body a to b (the static solver
    /// body is the index after the dynamic ones).
    void addContact(std::uint32_t a, std::uint32_t b, const Vec3& normal, int points)
    {
        IslandContact& contact = contacts.emplace_back();
        contact.solverA = a;
        contact.solverB = b;
        contact.manifold.normal = normal;
        contact.manifold.pointCount = points;
        contact.firstConstraint = static_cast<std::uint32_t>(constraints.size());
        for (int k = 0; k < points; ++k) {
            constraints.push_back(ContactConstraint{.bodyA = a, .bodyB = b, .normal = normal});
        }
    }
    /// Guesses every point; returns the total guessed normal impulse of contact `index`.
    void guessAll()
    {
        const std::vector<std::uint8_t> all(constraints.size(), 1);
        guessRestingImpulses(island, slots, contacts, constraints, all, Vec3(0, -kGravity, 0),
                             kTau);
    }
    [[nodiscard]] Real contactImpulse(std::size_t index) const
    {
        Real sum = 0.0;
        for (int k = 0; k < contacts[index].manifold.pointCount; ++k) {
            sum += constraints[contacts[index].firstConstraint + k].normalImpulse;
        }
        return sum;
    }
};

TEST(RestingLoadGuess, AColumnCarriesTheWeightAboveEachContact)
{
    // box 1 (2 kg) on box 0 (1 kg) on the ground: the upper face carries 2 g tau, the ground
    // 3 g tau, each spread equally over four points
    Scene scene;
    scene.addBody(1.0, Vec3(0, 0.5, 0));
    scene.addBody(2.0, Vec3(0, 1.5, 0));
    scene.addContact(2, 0, Vec3(0, 1, 0), 4);
    scene.addContact(0, 1, Vec3(0, 1, 0), 4);
    scene.guessAll();
    EXPECT_NEAR(scene.contactImpulse(0), 3.0 * kGravity * kTau, 1e-14);
    EXPECT_NEAR(scene.contactImpulse(1), 2.0 * kGravity * kTau, 1e-14);
    EXPECT_DOUBLE_EQ(scene.constraints[0].normalImpulse, scene.constraints[3].normalImpulse);
}

TEST(RestingLoadGuess, ALevelContactBesideABoxCarriesNoLoad)
{
    // box 1 rests on the ground beside box 0; their common normal is level up to rounding. The
    // ground carries each box's weight and the side contact nothing, not the whole weight
    // divided by the rounding
    Scene scene;
    scene.addBody(1.0, Vec3(0, 0.5, 0));
    scene.addBody(1.0, Vec3(1, 0.5, 0));
    scene.addContact(2, 0, Vec3(0, 1, 0), 4);
    scene.addContact(2, 1, Vec3(0, 1, 0), 4);
    scene.addContact(0, 1, glm::normalize(Vec3(1, 1e-16, 0)), 2);
    scene.guessAll();
    EXPECT_NEAR(scene.contactImpulse(0), kGravity * kTau, 1e-14);
    EXPECT_NEAR(scene.contactImpulse(1), kGravity * kTau, 1e-14);
    EXPECT_EQ(scene.contactImpulse(2), 0.0);
}

TEST(RestingLoadGuess, TwoSupportsShareTheLoadAsTheLeastNormForces)
{
    // a box on a level support (u = 1) and a 45-degree one (u = 1/sqrt 2): f_c = L u_c / sum u^2
    // = L u_c / 1.5, and the vertical parts f_c u_c sum to L
    Scene scene;
    scene.addBody(3.0, Vec3(0, 1, 0));
    scene.addContact(1, 0, Vec3(0, 1, 0), 1);
    scene.addContact(1, 0, glm::normalize(Vec3(1, 1, 0)), 1);
    scene.guessAll();
    const Real load = 3.0 * kGravity * kTau;
    const Real u = 1.0 / std::sqrt(2.0);
    EXPECT_NEAR(scene.contactImpulse(0), load / 1.5, 1e-14);
    EXPECT_NEAR(scene.contactImpulse(1), load * u / 1.5, 1e-14);
    EXPECT_NEAR(scene.contactImpulse(0) + u * scene.contactImpulse(1), load, 1e-14);
}

} // namespace
} // namespace tumble
