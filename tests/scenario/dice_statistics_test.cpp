// Dice statistics against values worked out by hand.
#include "tumble/scenario/dice_statistics.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

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

TEST(DiceStatistics, FairSumOfTwoDiceIsTheTriangle)
{
    const std::vector<Real> two = fairSumDistribution(2);
    ASSERT_EQ(two.size(), 11u);
    const std::array<int, 11> ways{1, 2, 3, 4, 5, 6, 5, 4, 3, 2, 1};
    for (std::size_t s = 0; s < ways.size(); ++s) {
        EXPECT_DOUBLE_EQ(two[s], ways[s] / 36.0) << "sum " << s + 2;
    }
    // three dice: 27 of the 216 outcomes sum to 10
    const std::vector<Real> three = fairSumDistribution(3);
    ASSERT_EQ(three.size(), 16u);
    EXPECT_DOUBLE_EQ(three[10 - 3], 27.0 / 216.0);
}

TEST(DiceStatistics, IndependenceOfAProductTableAndOfADiagonalOne)
{
    // rows (1, 2) times columns (1, 1, 2): exactly independent, X^2 = 0 on (2-1)(3-1) = 2 df
    const std::array<std::int64_t, 6> product{10, 10, 20, 20, 20, 40};
    const ChiSquareTest independent = chiSquareIndependence(product, 2, 3);
    EXPECT_NEAR(independent.statistic, 0.0, 1e-12);
    EXPECT_EQ(independent.degreesOfFreedom, 2);
    // a diagonal 2 x 2 table of 50 and 50: X^2 = n = 100 (phi = 1), by hand
    const std::array<std::int64_t, 4> diagonal{50, 0, 0, 50};
    const ChiSquareTest dependent = chiSquareIndependence(diagonal, 2, 2);
    EXPECT_NEAR(dependent.statistic, 100.0, 1e-9);
    EXPECT_EQ(dependent.degreesOfFreedom, 1);
    EXPECT_LT(chiSquarePValue(dependent.statistic, 1), 1e-20);
    // an empty row is left out of the degrees of freedom
    const std::array<std::int64_t, 6> emptyRow{0, 0, 0, 5, 7, 9};
    EXPECT_EQ(chiSquareIndependence(emptyRow, 2, 3).degreesOfFreedom, 0);
}

TEST(DiceStatistics, GoodnessOfFitAgainstGivenProbabilities)
{
    // 30 and 70 against 1/4 and 3/4 of 100: (30-25)^2/25 + (70-75)^2/75 = 1 + 1/3
    const std::array<std::int64_t, 2> counts{30, 70};
    const std::array<Real, 2> probabilities{0.25, 0.75};
    const ChiSquareTest test = chiSquareGoodnessOfFit(counts, probabilities);
    EXPECT_NEAR(test.statistic, 4.0 / 3.0, 1e-12);
    EXPECT_EQ(test.degreesOfFreedom, 1);
}

} // namespace
} // namespace tumble::scenario
