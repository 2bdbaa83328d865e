// Seeded random draws that give the same numbers on every machine: std::mt19937_64 (whose output
// the C++ standard fixes) mapped to reals by our own rule, because the standard distributions
// (std::uniform_real_distribution and the others) may differ between standard libraries.
#pragma once

#include "tumble/math.hpp"

#include <cstdint>
#include <random>

namespace tumble::scenario {

/// A stream of uniform draws from one seed.
class RandomDraws {
public:
    explicit RandomDraws(std::uint64_t seed) : m_engine(seed) {}

    /// Uniform in [0, 1): the top 53 bits of one 64-bit output, times 2^-53, so every double of
    /// the form k 2^-53 is equally likely.
    Real unit() { return static_cast<Real>(m_engine() >> 11) * 0x1.0p-53; }
    /// Uniform in [low, high] (exactly low when low == high).
    Real uniform(Real low, Real high) { return low + (high - low) * unit(); }
    /// A unit vector uniform on the sphere (Archimedes: the y component uniform in [-1, 1], the
    /// azimuth about y uniform): (sqrt(1 - y^2) cos a, y, sqrt(1 - y^2) sin a).
    Vec3 direction();
    /// A rotation uniform on SO(3) (Shoemake 1992, "Uniform random rotations", Graphics Gems
    /// III): three uniform numbers give a unit quaternion uniform on the 3-sphere.
    Quat rotation();

private:
    std::mt19937_64 m_engine;
};

} // namespace tumble::scenario
