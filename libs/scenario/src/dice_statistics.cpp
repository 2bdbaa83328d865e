// The statistics of a dice study: Wilson score intervals and Pearson's chi-square test. The
// distribution functions come from Boost.Math (normal quantile, regularised incomplete gamma).
#include "tumble/scenario/dice_statistics.hpp"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>

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

} // namespace tumble::scenario
