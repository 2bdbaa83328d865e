// Seeded random draws for the property tests: std::mt19937_64 (whose output sequence the C++
// standard fixes) with our own mapping to doubles, so a seed gives the same draws with every
// standard library (std::uniform_real_distribution's algorithm is not specified).
#pragma once

#include "tumble/math.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace tumble::robustness {

class Draws {
public:
    explicit Draws(std::uint64_t seed) : m_engine(seed) {}

    /// Uniform in [0, 1): the top 53 bits of one 64-bit output.
    Real unit() { return static_cast<Real>(m_engine() >> 11) * 0x1.0p-53; }
    /// Uniform in [low, high).
    Real uniform(Real low, Real high) { return low + (high - low) * unit(); }
    /// Log-uniform in [low, high) (both > 0): every decade equally likely.
    Real logUniform(Real low, Real high)
    {
        return std::exp(uniform(std::log(low), std::log(high)));
    }
    Vec3 vec3(Real low, Real high) { return {uniform(low, high), uniform(low, high), uniform(low, high)}; }
    /// A uniformly distributed rotation (Shoemake's method).
    Quat rotation()
    {
        const Real u1 = unit();
        const Real u2 = 2.0 * std::numbers::pi * unit();
        const Real u3 = 2.0 * std::numbers::pi * unit();
        const Real a = std::sqrt(1.0 - u1);
        const Real b = std::sqrt(u1);
        return Quat(a * std::cos(u2), a * std::sin(u2), b * std::sin(u3), b * std::cos(u3));
    }

private:
    std::mt19937_64 m_engine;
};

} // namespace tumble::robustness
