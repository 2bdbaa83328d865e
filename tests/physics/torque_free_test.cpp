// Torque-free motion of the handout cuboid (a symmetric top) against closed-form mechanics
// (docs/physics/02-integration.md, (2.9)-(2.10); Landau & Lifshitz, Mechanics, section 33).
#include "tumble/world.hpp"

#include "support/glm_printers.hpp"
#include "support/test_world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tumble {
namespace {

using testing::handoutCuboid;

/// 2 x 6 x 2, m = 2, w0 = (0.1, 0.1, 0.1), no gravity: I = (20/3, 4/3, 20/3), symmetry axis y.
BodyDef spinningTop()
{
    BodyDef def = handoutCuboid(2.0);
    def.angularVelocity = Vec3(0.1, 0.1, 0.1);
    return def;
}

/// Unwrapped angle change from `previous` to `current`, in (-pi, pi].
Real angleStep(Real previous, Real current)
{
    return std::remainder(current - previous, 2.0 * std::numbers::pi);
}

class TorqueFree : public ::testing::TestWithParam<Real> {};

TEST_P(TorqueFree, SymmetricTopConservesMomentumAndEnergyAndPrecessesAtTheClosedFormRate)
{
    const Real dt = GetParam();
    World world(WorldSettings{.gravity = Vec3(0.0)});
    const BodyId id = world.createBody(spinningTop());
    const Body& body = world.body(id);
    const Vec3 momentum0 = body.angularMomentum();
    const Real energy0 = body.kineticEnergy();
    const Vec3 inertia = body.inertiaBody();
    // (2.10): body frame, w precesses about the symmetry axis at (C - A)/A w_y = -0.08 rad/s.
    const Real bodyRate = (inertia.y - inertia.x) / inertia.x * 0.1;
    // (2.11): space frame, the symmetry axis precesses about L at |L| / A.
    const Real spaceRate = glm::length(momentum0) / inertia.x;
    ASSERT_NEAR(bodyRate, -0.08, 1e-15);

    Real largestMomentumError = 0.0;
    Real largestEnergyError = 0.0;
    Real bodyAngle = 0.0;
    Real spaceAngle = 0.0;
    const Vec3 axisL = glm::normalize(momentum0);
    Vec3 helper1;
    Vec3 helper2;
    orthonormalBasis(axisL, helper1, helper2);
    const auto bodyPhase = [&] {
        const Vec3 w = glm::conjugate(body.orientation) * body.angularVelocity;
        // A rotation about +y by theta turns atan2(z, x) by -theta.
        return -std::atan2(w.z, w.x);
    };
    const auto spacePhase = [&] {
        const Vec3 symmetryAxis = body.orientation * Vec3(0, 1, 0);
        return std::atan2(glm::dot(symmetryAxis, helper2), glm::dot(symmetryAxis, helper1));
    };
    Real previousBody = bodyPhase();
    Real previousSpace = spacePhase();
    const Real duration = 100.0;
    testing::simulate(world, duration, dt, [&](const World&) {
        largestMomentumError = std::max(
            largestMomentumError, glm::length(body.angularMomentum() - momentum0) / glm::length(momentum0));
        largestEnergyError =
            std::max(largestEnergyError, std::abs(body.kineticEnergy() / energy0 - 1.0));
        bodyAngle += angleStep(previousBody, bodyPhase());
        spaceAngle += angleStep(previousSpace, spacePhase());
        previousBody = bodyPhase();
        previousSpace = spacePhase();
    });
    EXPECT_LT(largestMomentumError, 1e-9);
    EXPECT_LT(largestEnergyError, 1e-6);
    EXPECT_NEAR(bodyAngle / duration, bodyRate, 1e-3 * std::abs(bodyRate));
    EXPECT_NEAR(spaceAngle / duration, spaceRate, 1e-3 * spaceRate);
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, TorqueFree,
                         ::testing::Values(1.0 / 60.0, 1.0 / 240.0, 1.0 / 960.0));

TEST(TorqueFree, HandoutIntegratorHoldsAngularVelocityAndLosesAngularMomentum)
{
    // The handouts' update keeps w constant in flight, so on the symmetric top w does not
    // precess and L = I(t) w is not conserved: the difference the default integrator fixes.
    World handout(WorldSettings{.gravity = Vec3(0.0), .integrator = Integrator::Handout});
    World exact(WorldSettings{.gravity = Vec3(0.0)});
    const BodyId handoutId = handout.createBody(spinningTop());
    const BodyId exactId = exact.createBody(spinningTop());
    const Vec3 momentum0 = exact.body(exactId).angularMomentum();
    testing::simulate(handout, 10.0, 1.0 / 240.0);
    testing::simulate(exact, 10.0, 1.0 / 240.0);

    EXPECT_TRUE(testing::near(handout.body(handoutId).angularVelocity, Vec3(0.1, 0.1, 0.1), 0.0));
    EXPECT_GT(glm::length(exact.body(exactId).angularVelocity - Vec3(0.1, 0.1, 0.1)), 1e-2);
    EXPECT_GT(glm::length(handout.body(handoutId).angularMomentum() - momentum0),
              1e-2 * glm::length(momentum0));
    EXPECT_LT(glm::length(exact.body(exactId).angularMomentum() - momentum0),
              1e-12 * glm::length(momentum0));
}

} // namespace
} // namespace tumble
