// The statistics of a dice study: Wilson score intervals for face probabilities and Pearson's
// chi-square test of uniformity (docs/dice.md, "Statistics").
#pragma once

#include "tumble/math.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace tumble::scenario {

/// A closed interval of probabilities.
struct ProbabilityInterval {
    Real low = 0.0;
    Real high = 1.0;
};

/// The two-sided standard normal quantile z with P(|Z| <= z) = confidence (1.96 for 0.95).
Real normalQuantile(Real confidence);

/// Wilson's score interval for a probability from `successes` out of `trials` (> 0) at the
/// given confidence (docs/dice.md, (D.1)). [0, 1] when trials is 0.
ProbabilityInterval wilsonInterval(std::int64_t successes, std::int64_t trials, Real confidence);

/// Pearson's statistic sum (O - E)^2 / E of `counts` against equal expected counts
/// E = total / counts.size() (docs/dice.md, (D.2)); 0 for no counts.
Real chiSquareUniformStatistic(std::span<const std::int64_t> counts);

/// P(X >= statistic) for X chi-square distributed with `degreesOfFreedom` (>= 1) degrees.
Real chiSquarePValue(Real statistic, int degreesOfFreedom);

/// A chi-square statistic and its degrees of freedom (0: the test does not apply).
struct ChiSquareTest {
    Real statistic = 0.0;
    int degreesOfFreedom = 0;
};

/// Pearson's test of independence of a rows x columns table of counts (row-major): expected
/// counts E_ij = row_i column_j / total (docs/dice.md, (D.3)); rows and columns with no count are
/// left out, and the degrees of freedom are (rows used - 1)(columns used - 1).
ChiSquareTest chiSquareIndependence(std::span<const std::int64_t> table, int rows, int columns);

/// The exact distribution of the sum of `dice` fair six-sided dice: element s - dice is
/// P(sum = s), for s from dice to 6 dice (the convolution of the uniform distribution).
std::vector<Real> fairSumDistribution(int dice);

/// Pearson's statistic sum (O - E)^2 / E of `counts` against E_i = total p_i; cells with p_i = 0
/// are skipped, and the degrees of freedom are the cells used minus 1.
ChiSquareTest chiSquareGoodnessOfFit(std::span<const std::int64_t> counts,
                                     std::span<const Real> probabilities);

} // namespace tumble::scenario
