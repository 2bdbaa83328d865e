#include "viewer/plot_history.hpp"

#include <gtest/gtest.h>

namespace tumble::viewer {
namespace {

PlotSample sampleAt(float time, float height = 0.0f)
{
    return {.time = time, .height = height, .kinetic = 2.0f * time, .total = 1.0f};
}

TEST(PlotHistory, KeepsOnlyTheWindow)
{
    PlotHistory history(2.0, 0.1);
    for (int i = 0; i <= 100; ++i) {
        history.record(sampleAt(0.1f * static_cast<float>(i)));
    }
    const auto& samples = history.samples();
    ASSERT_FALSE(samples.empty());
    EXPECT_NEAR(samples.back().time, 10.0f, 1e-4f);
    EXPECT_GE(samples.front().time, 8.0f - 1e-4f);
    EXPECT_LE(samples.size(), 22u);
}

TEST(PlotHistory, SamplesNoMoreOftenThanTheInterval)
{
    PlotHistory history(10.0, 1.0 / 120.0);
    // steps of 1/240 s: every second one is kept
    for (int step = 0; step <= 240; ++step) {
        history.record(sampleAt(static_cast<float>(step) / 240.0f));
    }
    EXPECT_EQ(history.samples().size(), 121u);
}

TEST(PlotHistory, TimeGoingBackClearsIt)
{
    PlotHistory history(10.0, 0.01);
    history.record(sampleAt(1.0f));
    history.record(sampleAt(2.0f));
    history.markCollision(1.5f);
    history.record(sampleAt(0.0f));
    EXPECT_EQ(history.samples().size(), 1u);
    EXPECT_TRUE(history.collisions().empty());
}

TEST(PlotHistory, CollisionMarksFollowTheWindow)
{
    PlotHistory history(1.0, 0.01);
    history.markCollision(0.2f);
    history.markCollision(0.9f);
    history.record(sampleAt(1.5f));
    ASSERT_EQ(history.collisions().size(), 1u);
    EXPECT_FLOAT_EQ(history.collisions()[0], 0.9f);
}

TEST(PlotHistory, RangeCoversTheKeptValues)
{
    PlotHistory history(10.0, 0.01);
    EXPECT_EQ(history.range(PlotQuantity::Height), std::make_pair(0.0f, 0.0f));
    history.record(sampleAt(0.0f, 3.0f));
    history.record(sampleAt(0.5f, -1.0f));
    history.record(sampleAt(1.0f, 2.0f));
    EXPECT_EQ(history.range(PlotQuantity::Height), std::make_pair(-1.0f, 3.0f));
    EXPECT_EQ(history.range(PlotQuantity::Kinetic), std::make_pair(0.0f, 2.0f));
}

TEST(PlotHistory, ValueOfPicksEachQuantity)
{
    const PlotSample sample{.time = 1.0f,
                            .height = 2.0f,
                            .speed = 3.0f,
                            .angularSpeed = 4.0f,
                            .kinetic = 5.0f,
                            .potential = 6.0f,
                            .total = 11.0f};
    EXPECT_EQ(valueOf(sample, PlotQuantity::Height), 2.0f);
    EXPECT_EQ(valueOf(sample, PlotQuantity::Speed), 3.0f);
    EXPECT_EQ(valueOf(sample, PlotQuantity::AngularSpeed), 4.0f);
    EXPECT_EQ(valueOf(sample, PlotQuantity::Kinetic), 5.0f);
    EXPECT_EQ(valueOf(sample, PlotQuantity::Potential), 6.0f);
    EXPECT_EQ(valueOf(sample, PlotQuantity::Total), 11.0f);
}

} // namespace
} // namespace tumble::viewer
