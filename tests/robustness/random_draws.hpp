// Seeded random draws for the property tests: the scenario library's RandomDraws (std::mt19937_64
// with our own mapping to doubles, the same on every standard library) plus the log-uniform and
// vector draws the properties use.
#pragma once

#include "tumble/scenario/random_draws.hpp"

#include <cmath>
#include <cstdint>

namespace tumble::robustness {

class Draws : public scenario::RandomDraws {
public:
    using RandomDraws::RandomDraws;

    /// Log-uniform in [low, high) (both > 0): every decade equally likely.
    Real logUniform(Real low, Real high)
    {
        return std::exp(uniform(std::log(low), std::log(high)));
    }
    Vec3 vec3(Real low, Real high)
    {
        // One draw per statement: the order of a constructor's arguments is unspecified.
        const Real x = uniform(low, high);
        const Real y = uniform(low, high);
        const Real z = uniform(low, high);
        return {x, y, z};
    }
};

} // namespace tumble::robustness
