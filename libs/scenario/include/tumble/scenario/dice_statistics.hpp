// The statistics of a dice study: Wilson score intervals for face probabilities and Pearson's
// chi-square test of uniformity (docs/dice.md, "Statistics").
#pragma once

#include "tumble/math.hpp"

#include <cstdint>
#include <span>

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

} // namespace tumble::scenario
