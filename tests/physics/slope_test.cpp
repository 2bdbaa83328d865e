// A cuboid on a tilted static plane against the closed forms of docs/physics/06-friction.md:
// sliding with a = g (sin t - mu cos t), holding when mu >= tan t, tipping when tan t > w / h.
#include "tumble/world.hpp"

#include "support/slope_world.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble {
namespace {

constexpr Real kPi = 3.14159265358979323846;
constexpr Real kGravity = 9.81;

using testing::Slope;

Slope makeSlope(Real degrees, Real friction, Real width, Real height)
{
    return testing::makeSlope(degrees, friction, width, height,
                              WorldSettings{.allowSleep = false});
}

void run(Slope& slope, Real duration, Real dt)
{
    for (int step = 0; step < static_cast<int>(std::lround(duration / dt)); ++step) {
        slope.world.step(dt);
    }
}

class SlidingDownASlope : public ::testing::TestWithParam<Real> {};

TEST_P(SlidingDownASlope, TravelsHalfOfGSinMinusMuCosTimesTSquared)
{
    // (6.6): a = g (sin t - mu cos t), d = a T^2 / 2 after T = 2 s, for 30 degrees and mu = 0.3
    const Real dt = GetParam();
    Slope slope = makeSlope(30.0, 0.3, 1.0, 1.0);
    const Vec3 start = slope.world.body(slope.box).position;
    run(slope, 2.0, dt);
    const Real angle = kPi / 6.0;
    const Real expected = 0.5 * kGravity * (std::sin(angle) - 0.3 * std::cos(angle)) * 4.0;
    const Vec3 travel = slope.world.body(slope.box).position - start;
    EXPECT_NEAR(glm::dot(travel, slope.downhill), expected, 1e-4);
    EXPECT_NEAR(glm::length(travel - glm::dot(travel, slope.downhill) * slope.downhill), 0.0,
                1e-6);
}

INSTANTIATE_TEST_SUITE_P(Steps, SlidingDownASlope,
                         ::testing::Values(1.0 / 60, 1.0 / 240, 1.0 / 480));

TEST(HoldingOnASlope, StaysPutWhenFrictionIsAtLeastTheTangentAndSlidesJustBelowIt)
{
    // (6.6): at 20 degrees tan t = 0.364; mu = 0.37 holds, mu = 0.35 slides
    Slope holds = makeSlope(20.0, 0.37, 1.0, 1.0);
    const Vec3 start = holds.world.body(holds.box).position;
    run(holds, 2.0, 1.0 / 240);
    EXPECT_LT(glm::length(holds.world.body(holds.box).position - start), 1e-6);

    Slope slides = makeSlope(20.0, 0.35, 1.0, 1.0);
    run(slides, 2.0, 1.0 / 240);
    const Real angle = 20.0 * kPi / 180.0;
    const Real expected = 0.5 * kGravity * (std::sin(angle) - 0.35 * std::cos(angle)) * 4.0;
    EXPECT_NEAR(glm::dot(slides.world.body(slides.box).position - start, slides.downhill),
                expected, 1e-4);
}

TEST(TippingOnASlope, ATallBoxTipsWhenTheTangentPassesWidthOverHeight)
{
    // a box 0.5 wide and 1.5 tall (w / h = 1/3, 18.4 degrees) on a slope too rough to slide:
    // at 15 degrees its centre stays over its base; at 22 degrees it tips over the lower edge
    Slope stands = makeSlope(15.0, 1.0, 0.5, 1.5);
    const Quat upright = stands.world.body(stands.box).orientation;
    run(stands, 2.0, 1.0 / 240);
    EXPECT_GT(std::abs(glm::dot(stands.world.body(stands.box).orientation, upright)),
              1.0 - 1e-9);

    Slope tips = makeSlope(22.0, 1.0, 0.5, 1.5);
    const Quat start = tips.world.body(tips.box).orientation;
    run(tips, 2.0, 1.0 / 240);
    // turned by more than 30 degrees: cos(15 degrees) of the quaternion's half angle
    EXPECT_LT(std::abs(glm::dot(tips.world.body(tips.box).orientation, start)),
              std::cos(15.0 * kPi / 180.0));
}

} // namespace
} // namespace tumble
