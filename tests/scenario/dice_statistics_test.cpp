// Dice statistics against values worked out by hand.
#include "tumble/scenario/dice_statistics.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>

namespace tumble::scenario {
namespace {

TEST(DiceStatistics, NormalQuantileOfTheUsualConfidences)
{
    EXPECT_NEAR(normalQuantile(0.95), 1.959963984540054, 1e-12);
    EXPECT_NEAR(normalQuantile(0.999), 3.290526731491926, 1e-12);
}

TEST(DiceStatistics, WilsonIntervalOfHalf)
{
    // k = 50, n = 100, z = 1.959964: p = 0.5, z^2/n = 0.0384146, so the centre stays 0.5 and
    // the half width is z sqrt(0.25/100 + 0.0384146/400) / 1.0384146 = 0.0961685
    const ProbabilityInterval interval = wilsonInterval(50, 100, 0.95);
    EXPECT_NEAR(interval.low, 0.4038315303659956, 1e-12);
    EXPECT_NEAR(interval.high, 0.5961684696340044, 1e-12);
}

TEST(DiceStatistics, WilsonIntervalOfNoSuccesses)
{
    // k = 0: the centre is (z^2/2n) / (1 + z^2/n) and the half width the same, so the interval
    // is [0, z^2 / (n + z^2)] = [0, 3.841459 / 13.841459] for n = 10
    const ProbabilityInterval interval = wilsonInterval(0, 10, 0.95);
    EXPECT_NEAR(interval.low, 0.0, 1e-15);
    EXPECT_NEAR(interval.high, 0.2775327998628892, 1e-12);
}

TEST(DiceStatistics, WilsonIntervalOfFourInTwenty)
{
    // p = 0.2, n = 20: centre (0.2 + 0.0960365) / 1.192073 = 0.248338, half width
    // 1.959964 sqrt(0.008 + 0.0004802) / 1.192073 = 0.167679 (Newcombe 1998 gives
    // 0.0807-0.4160)
    const ProbabilityInterval interval = wilsonInterval(4, 20, 0.95);
    EXPECT_NEAR(interval.low, 0.08065766257979806, 1e-12);
    EXPECT_NEAR(interval.high, 0.41601743225189364, 1e-12);
}

TEST(DiceStatistics, ChiSquareStatisticAgainstEqualCounts)
{
    // O = (30, 20, 10), E = 20 each: (100 + 0 + 100) / 20 = 10
    const std::array<std::int64_t, 3> counts{30, 20, 10};
    EXPECT_DOUBLE_EQ(chiSquareUniformStatistic(counts), 10.0);
    const std::array<std::int64_t, 6> fair{5, 5, 5, 5, 5, 5};
    EXPECT_EQ(chiSquareUniformStatistic(fair), 0.0);
}

TEST(DiceStatistics, ChiSquarePValuesInClosedForm)
{
    // for 2 degrees of freedom the survival function is exp(-x/2): x = 10 gives exp(-5)
    EXPECT_NEAR(chiSquarePValue(10.0, 2), std::exp(-5.0), 1e-14);
    // for 4 it is exp(-x/2) (1 + x/2): x = 6 gives 4 exp(-3)
    EXPECT_NEAR(chiSquarePValue(6.0, 4), 4.0 * std::exp(-3.0), 1e-14);
    // the tabulated 5% critical value of 5 degrees of freedom is 11.0705
    EXPECT_NEAR(chiSquarePValue(11.0705, 5), 0.05, 1e-5);
    EXPECT_EQ(chiSquarePValue(0.0, 5), 1.0);
}

} // namespace
} // namespace tumble::scenario
