// Torque-free rotation: the exact splitting and the handouts' update
// (docs/physics/02-integration.md, (2.4)-(2.8)).
#include "dynamics/integrator.hpp"

#include "support/glm_printers.hpp"
#include "support/test_world.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble {
namespace {

using testing::near;
using testing::sameRotation;

TEST(Integrator, ExactRotationAboutAPrincipalAxisIsTheClosedFormRotation)
{
    // Spin about a principal axis is steady: q(t) = q0 * rot(axis, w t) for any dt.
    const Vec3 inertia = cuboidInertiaDiagonal(2.0, Vec3(1, 2, 3));
    Quat orientation(1, 0, 0, 0);
    Vec3 angularVelocity(0, 0, 1.3);
    for (int i = 0; i < 100; ++i) {
        integrateRotation(orientation, angularVelocity, inertia, 0.05, Integrator::Exact);
    }
    EXPECT_TRUE(sameRotation(orientation, axisAngle(Vec3(0, 0, 1), 1.3 * 5.0), 1e-14));
    EXPECT_TRUE(near(angularVelocity, Vec3(0, 0, 1.3), 1e-13));
}

TEST(Integrator, ExactIsExactForTheSymmetricTopEvenAtLargeSteps)
{
    // Symmetric top, symmetry axis y: A = Ix = Iz, C = Iy. Euler's equations give w_y constant
    // and, with Omega = (A - C)/A w_y, dw_x/dt = -Omega w_z, dw_z/dt = Omega w_x, so
    // w_x = a cos(Omega t) - b sin(Omega t), w_z = a sin(Omega t) + b cos(Omega t)
    // (docs/physics/02-integration.md, (2.9)).
    const Vec3 inertia = cuboidInertiaDiagonal(2.0, Vec3(2, 6, 2)); // (20/3, 4/3, 20/3)
    const Real omega = (inertia.x - inertia.y) / inertia.x * 0.1;   // 0.08 rad/s
    Quat orientation(1, 0, 0, 0);
    Vec3 angularVelocity(0.1, 0.1, 0.1);
    const Real dt = 0.5; // deliberately huge: the split is exact here, not just accurate
    for (int i = 0; i < 40; ++i) {
        integrateRotation(orientation, angularVelocity, inertia, dt, Integrator::Exact);
    }
    const Real angle = omega * 20.0;
    const Vec3 bodyFrame = glm::conjugate(orientation) * angularVelocity;
    const Vec3 expected(0.1 * std::cos(angle) - 0.1 * std::sin(angle), 0.1,
                        0.1 * std::sin(angle) + 0.1 * std::cos(angle));
    EXPECT_TRUE(near(bodyFrame, expected, 1e-13));
}

TEST(Integrator, ExactConservesAngularMomentumAndBoundsEnergyNearTheIntermediateAxis)
{
    // A 1 x 2 x 3 box spun about y (its intermediate axis) with a small perturbation flips
    // periodically (Dzhanibekov). World L is conserved to rounding; the energy error of the
    // second-order split stays small and bounded.
    const Vec3 inertia = cuboidInertiaDiagonal(1.0, Vec3(1, 2, 3));
    Quat orientation(1, 0, 0, 0);
    Vec3 angularVelocity(0.01, 4.0, 0.01);
    const auto energy = [&] {
        const Vec3 local = glm::conjugate(orientation) * angularVelocity;
        return 0.5 * glm::dot(local, inertia * local);
    };
    const auto momentum = [&] {
        return orientation * (inertia * (glm::conjugate(orientation) * angularVelocity));
    };
    const Real energy0 = energy();
    const Vec3 momentum0 = momentum();
    Real largestEnergyError = 0.0;
    int flips = 0;
    Real previousSpin = 4.0;
    const Real dt = 1.0 / 240.0;
    for (int i = 0; i < 4800; ++i) {
        integrateRotation(orientation, angularVelocity, inertia, dt, Integrator::Exact);
        largestEnergyError = std::max(largestEnergyError, std::abs(energy() / energy0 - 1.0));
        EXPECT_LT(glm::length(momentum() - momentum0), 1e-11 * glm::length(momentum0));
        const Real spin = (glm::conjugate(orientation) * angularVelocity).y;
        flips += spin * previousSpin < 0.0 ? 1 : 0;
        previousSpin = spin;
    }
    EXPECT_GE(flips, 2);
    EXPECT_LT(largestEnergyError, 1e-5);
}

TEST(Integrator, ExactEnergyErrorIsSecondOrder)
{
    const Vec3 inertia = cuboidInertiaDiagonal(1.0, Vec3(1, 2, 3));
    const auto largestEnergyError = [&](Real dt) {
        Quat orientation(1, 0, 0, 0);
        Vec3 angularVelocity(0.01, 4.0, 0.01);
        const Real energy0 = 0.5 * glm::dot(angularVelocity, inertia * angularVelocity);
        Real largest = 0.0;
        for (long i = 0; i < std::lround(5.0 / dt); ++i) {
            integrateRotation(orientation, angularVelocity, inertia, dt, Integrator::Exact);
            const Vec3 local = glm::conjugate(orientation) * angularVelocity;
            largest = std::max(largest, std::abs(0.5 * glm::dot(local, inertia * local) / energy0 - 1));
        }
        return largest;
    };
    // Halving dt divides a second-order error by about 4.
    const Real ratio = largestEnergyError(1.0 / 120.0) / largestEnergyError(1.0 / 240.0);
    EXPECT_GT(ratio, 3.5);
    EXPECT_LT(ratio, 4.5);
}

TEST(Integrator, ExactStaysAccurateWhenSpunFarPastHalfARadianPerStep)
{
    // An impact at the tip of a thin body can spin it to several radians per step. One split
    // composition per step then gained 52 % energy here; the step is now divided so that no
    // composition turns more than 0.5 rad, up to 8 compositions per step (2.7a).
    const Vec3 inertia = cuboidInertiaDiagonal(1.0, Vec3(1, 2, 3));
    Quat orientation(1, 0, 0, 0);
    Vec3 angularVelocity(60, 200, 30); // about 2.6 rad per step at dt = 1/80
    const auto energy = [&] {
        const Vec3 local = glm::conjugate(orientation) * angularVelocity;
        return 0.5 * glm::dot(local, inertia * local);
    };
    const Real energy0 = energy();
    Real largestError = 0.0;
    for (int i = 0; i < 2000; ++i) {
        integrateRotation(orientation, angularVelocity, inertia, 1.0 / 80.0, Integrator::Exact);
        largestError = std::max(largestError, std::abs(energy() / energy0 - 1.0));
    }
    EXPECT_LT(largestError, 2e-3);
}

TEST(Integrator, HandoutKeepsAngularVelocityConstantAndSoNeverFlips)
{
    const Vec3 inertia = cuboidInertiaDiagonal(1.0, Vec3(1, 2, 3));
    Quat orientation(1, 0, 0, 0);
    Vec3 angularVelocity(0.01, 4.0, 0.01);
    for (int i = 0; i < 4800; ++i) {
        integrateRotation(orientation, angularVelocity, inertia, 1.0 / 240.0, Integrator::Handout);
    }
    EXPECT_TRUE(near(angularVelocity, Vec3(0.01, 4.0, 0.01), 0.0));
    EXPECT_NEAR(glm::length(orientation), 1.0, 1e-14);
}

TEST(Integrator, HandoutIsFirstOrderAccurateForSteadySpin)
{
    // About a fixed axis R += dt [w]x R rotates by atan(w dt) per step after normalisation:
    // the angle error per step is O(dt^3), but the method is first order for general motion;
    // for steady spin the orientation still tracks the exact rotation closely.
    const Vec3 inertia = cuboidInertiaDiagonal(1.0, Vec3(2, 2, 2));
    Quat orientation(1, 0, 0, 0);
    Vec3 angularVelocity(0, 0, 1.0);
    const Real dt = 1.0 / 240.0;
    for (int i = 0; i < 240; ++i) {
        integrateRotation(orientation, angularVelocity, inertia, dt, Integrator::Handout);
    }
    const Real perStep = std::atan(dt);
    EXPECT_TRUE(sameRotation(orientation, axisAngle(Vec3(0, 0, 1), 240 * perStep), 1e-12));
}

} // namespace
} // namespace tumble
