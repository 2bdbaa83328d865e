// The statistics of a dice study: Wilson score intervals and Pearson's chi-square test. The
// distribution functions come from Boost.Math (normal quantile, regularised incomplete gamma).
#include "tumble/scenario/dice_statistics.hpp"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace tumble::scenario {

Real normalQuantile(Real confidence)
{
    const boost::math::normal_distribution<Real> standard;
    return boost::math::quantile(standard, 0.5 + 0.5 * confidence);
}

ProbabilityInterval wilsonInterval(std::int64_t successes, std::int64_t trials, Real confidence)
{
    if (trials <= 0) {
        return {};
    }
    // (D.1): (p + z^2/2n +- z sqrt(p(1-p)/n + z^2/4n^2)) / (1 + z^2/n)
    const Real z = normalQuantile(confidence);
    const auto n = static_cast<Real>(trials);
    const Real p = static_cast<Real>(successes) / n;
    const Real z2n = z * z / n;
    const Real centre = (p + 0.5 * z2n) / (1.0 + z2n);
    const Real halfWidth = z * std::sqrt(p * (1.0 - p) / n + 0.25 * z2n / n) / (1.0 + z2n);
    return {std::max(0.0, centre - halfWidth), std::min(1.0, centre + halfWidth)};
}

Real chiSquareUniformStatistic(std::span<const std::int64_t> counts)
{
    const std::int64_t total = std::accumulate(counts.begin(), counts.end(), std::int64_t{0});
    if (counts.empty() || total == 0) {
        return 0.0;
    }
    // (D.2) with every expected count E = total / k
    const Real expected = static_cast<Real>(total) / static_cast<Real>(counts.size());
    Real statistic = 0.0;
    for (const std::int64_t observed : counts) {
        const Real difference = static_cast<Real>(observed) - expected;
        statistic += difference * difference / expected;
    }
    return statistic;
}

Real chiSquarePValue(Real statistic, int degreesOfFreedom)
{
    const boost::math::chi_squared_distribution<Real> distribution(degreesOfFreedom);
    return boost::math::cdf(boost::math::complement(distribution, std::max(0.0, statistic)));
}

ChiSquareTest chiSquareIndependence(std::span<const std::int64_t> table, int rows, int columns)
{
    const auto at = [&](int i, int j) {
        return static_cast<Real>(table[static_cast<std::size_t>(i * columns + j)]);
    };
    std::vector<Real> rowTotals(static_cast<std::size_t>(rows), 0.0);
    std::vector<Real> columnTotals(static_cast<std::size_t>(columns), 0.0);
    Real total = 0.0;
    for (int i = 0; i < rows; ++i) {
        for (int j = 0; j < columns; ++j) {
            rowTotals[static_cast<std::size_t>(i)] += at(i, j);
            columnTotals[static_cast<std::size_t>(j)] += at(i, j);
            total += at(i, j);
        }
    }
    const auto used = [](const std::vector<Real>& totals) {
        return static_cast<int>(std::count_if(totals.begin(), totals.end(),
                                              [](Real t) { return t > 0.0; }));
    };
    ChiSquareTest test;
    test.degreesOfFreedom = std::max(0, (used(rowTotals) - 1) * (used(columnTotals) - 1));
    for (int i = 0; i < rows; ++i) {
        for (int j = 0; j < columns; ++j) {
            const Real expected = rowTotals[static_cast<std::size_t>(i)] *
                                  columnTotals[static_cast<std::size_t>(j)] / total;
            if (expected > 0.0) {
                const Real difference = at(i, j) - expected;
                test.statistic += difference * difference / expected;
            }
        }
    }
    return test;
}

std::vector<Real> fairSumDistribution(int dice)
{
    // counts of the ways to reach each sum, convolved one die at a time (exact in doubles: at
    // most 6^dice ways, far below 2^53 for the dice of a throw)
    std::vector<Real> ways{1.0};
    Real outcomes = 1.0;
    for (int d = 0; d < dice; ++d) {
        std::vector<Real> next(ways.size() + 5, 0.0);
        for (std::size_t s = 0; s < ways.size(); ++s) {
            for (std::size_t face = 0; face < 6; ++face) {
                next[s + face] += ways[s];
            }
        }
        ways = std::move(next);
        outcomes *= 6.0;
    }
    for (Real& w : ways) {
        w /= outcomes;
    }
    return ways;
}

ChiSquareTest chiSquareGoodnessOfFit(std::span<const std::int64_t> counts,
                                     std::span<const Real> probabilities)
{
    const std::int64_t total = std::accumulate(counts.begin(), counts.end(), std::int64_t{0});
    ChiSquareTest test;
    int cells = 0;
    for (std::size_t i = 0; i < counts.size(); ++i) {
        const Real expected = static_cast<Real>(total) * probabilities[i];
        if (expected > 0.0) {
            const Real difference = static_cast<Real>(counts[i]) - expected;
            test.statistic += difference * difference / expected;
            ++cells;
        }
    }
    test.degreesOfFreedom = std::max(0, cells - 1);
    return test;
}

} // namespace tumble::scenario
