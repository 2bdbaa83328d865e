#include "viewer/fixed_step.hpp"

#include <gtest/gtest.h>

namespace tumble::viewer {
namespace {

constexpr double kDt = 1.0 / 240.0;

TEST(FixedStepAccumulator, SixtyFramesOfASixtiethMakeOneSecondOfSteps)
{
    FixedStepAccumulator accumulator(kDt, 100);
    int steps = 0;
    for (int frame = 0; frame < 60; ++frame) {
        const int due = accumulator.advance(1.0 / 60.0, 1.0);
        EXPECT_EQ(due, 4);
        steps += due;
    }
    EXPECT_EQ(steps, 240);
    EXPECT_NEAR(accumulator.pending(), 0.0, 1e-12);
}

TEST(FixedStepAccumulator, FrameTimeNeverBecomesTheStep)
{
    // uneven frames: each step is still dt, the remainder waits for the next frame
    FixedStepAccumulator accumulator(kDt, 100);
    const double frames[] = {0.007, 0.011, 0.0165, 0.002, 0.03};
    double simulated = 0.0;
    double real = 0.0;
    for (const double frame : frames) {
        simulated += accumulator.advance(frame, 1.0) * kDt;
        real += frame;
        EXPECT_NEAR(simulated + accumulator.pending(), real, 1e-12);
        EXPECT_GE(accumulator.pending(), 0.0);
        EXPECT_LT(accumulator.pending(), kDt);
    }
}

TEST(FixedStepAccumulator, TimeScaleSlowsAndSpeedsUp)
{
    FixedStepAccumulator slow(kDt, 100);
    FixedStepAccumulator fast(kDt, 100);
    int slowSteps = 0;
    int fastSteps = 0;
    for (int frame = 0; frame < 60; ++frame) {
        slowSteps += slow.advance(1.0 / 60.0, 0.1);
        fastSteps += fast.advance(1.0 / 60.0, 2.0);
    }
    EXPECT_EQ(slowSteps, 24);
    EXPECT_EQ(fastSteps, 480);
}

TEST(FixedStepAccumulator, BacklogBeyondTheLimitIsDropped)
{
    FixedStepAccumulator accumulator(kDt, 10);
    EXPECT_EQ(accumulator.advance(0.2, 1.0), 10);
    EXPECT_TRUE(accumulator.fellBehind());
    EXPECT_EQ(accumulator.pending(), 0.0);
    EXPECT_EQ(accumulator.advance(1.0 / 60.0, 1.0), 4);
    EXPECT_FALSE(accumulator.fellBehind());
}

TEST(FixedStepAccumulator, LongStallCountsAsAQuarterSecond)
{
    FixedStepAccumulator accumulator(kDt, 1000);
    EXPECT_EQ(accumulator.advance(5.0, 1.0), 60);
}

TEST(FixedStepAccumulator, NegativeFrameTimeAddsNothing)
{
    FixedStepAccumulator accumulator(kDt, 10);
    EXPECT_EQ(accumulator.advance(-1.0, 1.0), 0);
    EXPECT_EQ(accumulator.pending(), 0.0);
}

TEST(FixedStepAccumulator, SetDtDropsPendingTime)
{
    FixedStepAccumulator accumulator(kDt, 10);
    accumulator.advance(0.5 * kDt, 1.0);
    EXPECT_GT(accumulator.pending(), 0.0);
    accumulator.setDt(0.01);
    EXPECT_EQ(accumulator.pending(), 0.0);
    EXPECT_EQ(accumulator.dt(), 0.01);
}

} // namespace
} // namespace tumble::viewer
