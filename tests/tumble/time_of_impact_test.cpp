// The time of impact of a vertex not yet touching the ground (docs/physics/04-detection.md,
// (4.3)-(4.4)).
#include "collision/time_of_impact.hpp"

#include "collision/collide_cuboid_plane.hpp"
#include "tumble/shape.hpp"

#include "support/glm_printers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>

namespace tumble {
namespace {

/// The impact tolerance of the default world: 1e-4 of the 1e-4 m contact tolerance.
constexpr Real kImpactTolerance = 1e-8;

Real search(const SubstepMotion& motion, const Vec3& halfExtents)
{
    int advances = 0;
    return timeOfImpact(motion, halfExtents, Plane{}, 0u, kImpactTolerance, advances);
}

/// A 1000 x 1 x 1 stick at a random orientation, turning and falling slowly, with its lowest
/// vertex `height` above the plane.
SubstepMotion fallingStick(std::mt19937_64& random, Real height, Integrator integrator)
{
    std::uniform_real_distribution<Real> component(-1.0, 1.0);
    const Vec3 halfExtents(500.0, 0.5, 0.5);
    SubstepMotion motion;
    motion.start.orientation = glm::normalize(
        Quat(component(random), component(random), component(random), component(random)));
    const Real lowest =
        lowestVertexHeight({Vec3(0.0), motion.start.orientation}, halfExtents, Plane{});
    motion.start.position = Vec3(0.0, height - lowest, 0.0);
    motion.velocityStart = Vec3(0.0, -1e-3, 0.0);
    motion.velocityEnd = Vec3(0.0, -1e-3, 0.0);
    motion.angularVelocity = 1e-3 * Vec3(component(random), component(random), component(random));
    motion.inertiaBody = cuboidInertiaDiagonal(1e-6, 2.0 * halfExtents);
    motion.tau = 0.1;
    motion.integrator = integrator;
    return motion;
}

TEST(TimeOfImpact, ThePoseAtTheStartIsExactlyTheStartPose)
{
    std::mt19937_64 random(6);
    for (const Integrator integrator : {Integrator::Exact, Integrator::Handout}) {
        for (int draw = 0; draw < 100; ++draw) {
            const SubstepMotion motion = fallingStick(random, 1.0, integrator);
            const Transform pose = poseAt(motion, 0.0);
            EXPECT_EQ(pose.position, motion.start.position);
            EXPECT_EQ(pose.orientation, motion.start.orientation);
        }
    }
}

// Found by world_step_fuzzer (tests/fuzz/regressions/world_step/handout_stick_zero_substep):
// the world leaves an approaching vertex higher than the impact tolerance to the time of impact,
// but the handout rotation over s = 0 (Gram-Schmidt and back to a quaternion) moved the stick's
// far vertices by 3e-14 m, so the search saw such a vertex within the tolerance, returned s = 0,
// and the zero-length sub-step divided by zero in (5.9).
TEST(TimeOfImpact, AVertexJustAboveTheToleranceGivesAPositiveTime)
{
    const Vec3 halfExtents(500.0, 0.5, 0.5);
    std::mt19937_64 random(6);
    for (const Integrator integrator : {Integrator::Exact, Integrator::Handout}) {
        int searched = 0;
        for (int draw = 0; draw < 1000; ++draw) {
            // within a few ulps of 500 m above the tolerance
            const Real height = kImpactTolerance + 1e-13 * (draw % 20);
            const SubstepMotion motion = fallingStick(random, height, integrator);
            // the world's test: a vertex within the impact tolerance is an impact now
            if (lowestVertexHeight(motion.start, halfExtents, Plane{}) <= kImpactTolerance) {
                continue;
            }
            ++searched;
            EXPECT_GT(search(motion, halfExtents), 0.0)
                << "draw " << draw;
        }
        EXPECT_GT(searched, 500);
    }
}

// (4.4a) on a closed form: a cube of half-edge 1, axis-aligned, turning about z at w with its
// centre fixed at height y_c. At angle theta in [0, pi/4] its lowest vertex is at
// y_c - sqrt(2) cos(pi/4 - theta), so it reaches height x at theta_x = pi/4 - acos((y_c - x)/
// sqrt(2)). The search aims at half the tolerance and stops within the tolerance, so it must
// return a time between theta_tol / w and theta_(tol/2) / w; a cube is a spherical top, so the
// quadratic advances are the ones used.
TEST(TimeOfImpact, ACubeTurningOntoItsEdgeMeetsThePlaneWhenTheClosedFormSays)
{
    const Vec3 halfExtents(1.0);
    const Real root2 = std::sqrt(2.0);
    for (const Real spin : {0.01, 1.0, 30.0}) {
        for (const Real centreHeight : {1.05, 1.2, 1.4}) {
            SubstepMotion motion;
            motion.start.position = Vec3(0.0, centreHeight, 0.0);
            motion.angularVelocity = Vec3(0.0, 0.0, spin);
            motion.inertiaBody = cuboidInertiaDiagonal(1.0, 2.0 * halfExtents);
            motion.tau = 1.0 / spin;
            const auto timeAtHeight = [&](Real height) {
                return (0.25 * std::numbers::pi - std::acos((centreHeight - height) / root2)) /
                       spin;
            };
            const Real found = search(motion, halfExtents);
            EXPECT_GE(found, timeAtHeight(kImpactTolerance) * (1.0 - 1e-9))
                << "spin " << spin << ", centre at " << centreHeight;
            EXPECT_LE(found, timeAtHeight(0.5 * kImpactTolerance) * (1.0 + 1e-9))
                << "spin " << spin << ", centre at " << centreHeight;
        }
    }
}

// (4.4) and (4.4a) never step past the aim of half the tolerance: random spherical, symmetric
// and general cuboids (the last two use (4.4) alone), the last a needle of nearly equal
// thicknesses spinning mostly about its long axis (the world-stepping fuzzer's slow case: its
// vertices move at the spin times their distance from the axis), random spins, falls and
// decelerations, each motion sampled densely up to the time found.
TEST(TimeOfImpact, NeverStepsPastACrossing)
{
    std::mt19937_64 random(44);
    std::uniform_real_distribution<Real> unit(0.0, 1.0);
    std::uniform_real_distribution<Real> component(-1.0, 1.0);
    const std::array<Vec3, 4> sizes{Vec3(0.02), Vec3(2.0, 6.0, 2.0), Vec3(1.0, 2.0, 3.0),
                                    Vec3(1.0, 1e-3, 1.0001e-3)};
    int crossings = 0;
    for (int draw = 0; draw < 800; ++draw) {
        const std::size_t kind = static_cast<std::size_t>(draw % 4);
        const Vec3 halfExtents = 0.5 * sizes[kind];
        const Real scale = glm::length(halfExtents);
        SubstepMotion motion;
        motion.start.orientation = glm::normalize(
            Quat(component(random), component(random), component(random), component(random)));
        const Real lowest =
            lowestVertexHeight({Vec3(0.0), motion.start.orientation}, halfExtents, Plane{});
        motion.start.position = Vec3(0.0, 0.05 * scale * unit(random) - lowest + 2e-8, 0.0);
        motion.tau = 0.02 * unit(random) + 1e-4;
        motion.velocityStart = scale * Vec3(component(random), component(random), component(random));
        motion.velocityEnd = motion.velocityStart + motion.tau * Vec3(0.0, -9.81, 0.0) +
                             0.1 * scale * Vec3(0.0, component(random), 0.0);
        motion.angularVelocity = 20.0 * unit(random) *
                                 glm::normalize(Vec3(component(random), component(random),
                                                     component(random)));
        if (kind == 3) {
            motion.angularVelocity += 3000.0 * unit(random) * (motion.start.orientation *
                                                               Vec3(1.0, 0.0, 0.0));
        }
        motion.inertiaBody = cuboidInertiaDiagonal(1.0, 2.0 * halfExtents);
        const Real found = search(motion, halfExtents);
        ASSERT_GE(found, 0.0);
        ASSERT_LE(found, motion.tau);
        // With (4.4) alone a general cuboid may run out of advances before its vertex arrives,
        // which returns an earlier, safe time; (4.4a) arrives.
        const bool quadratic = kind < 2;
        if (found < motion.tau && quadratic) {
            ++crossings;
            EXPECT_LE(freeClearance(motion, halfExtents, Plane{}, 0u, found), kImpactTolerance)
                << "draw " << draw;
        }
        constexpr int kSamples = 2000;
        for (int sample = 0; sample <= kSamples; ++sample) {
            const Real s = found * sample / kSamples;
            // the aim, less the rounding of heights a few metres from the centre
            ASSERT_GT(freeClearance(motion, halfExtents, Plane{}, 0u, s),
                      0.5 * kImpactTolerance - 1e-13)
                << "draw " << draw << " stepped past a crossing before s = " << s;
        }
    }
    EXPECT_GT(crossings, 100);
}

} // namespace
} // namespace tumble
