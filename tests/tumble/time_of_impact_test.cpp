// The time of impact of a vertex not yet touching the ground (docs/physics/04-detection.md,
// (4.3)-(4.4)).
#include "collision/time_of_impact.hpp"

#include "collision/collide_cuboid_plane.hpp"
#include "tumble/shape.hpp"

#include "support/glm_printers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace tumble {
namespace {

/// The impact tolerance of the default world: 1e-4 of the 1e-4 m contact tolerance.
constexpr Real kImpactTolerance = 1e-8;

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
            EXPECT_GT(timeOfImpact(motion, halfExtents, Plane{}, 0u, kImpactTolerance), 0.0)
                << "draw " << draw;
        }
        EXPECT_GT(searched, 500);
    }
}

} // namespace
} // namespace tumble
