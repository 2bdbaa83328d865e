// Drawing a throw's initial state: one std::mt19937_64 per (seed, index), our own mapping to
// [0, 1), Shoemake's uniform rotation and uniform directions (docs/dice.md, "Drawing a throw").
#include "tumble/scenario/throw.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace tumble::scenario {

namespace {

/// splitmix64 (Steele, Lea and Flood 2014): a bijective mix of all 64 bits, used to spread
/// consecutive seeds and indices far apart before they seed the Mersenne Twister.
std::uint64_t splitmix64(std::uint64_t x)
{
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30U)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27U)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31U);
}

/// Uniform on [0, 1) from the top 53 bits of one draw: exactly representable, and the same on
/// every standard library (std::uniform_real_distribution is not).
Real unitUniform(std::mt19937_64& generator)
{
    return static_cast<Real>(generator() >> 11U) * 0x1.0p-53;
}

Real uniformIn(std::mt19937_64& generator, const DrawRange& range)
{
    return range.min + (range.max - range.min) * unitUniform(generator);
}

/// Shoemake, "Uniform random rotations", Graphics Gems III (1992): uniform on SO(3).
Quat uniformRotation(std::mt19937_64& generator)
{
    const Real u1 = unitUniform(generator);
    const Real theta1 = 2.0 * std::numbers::pi * unitUniform(generator);
    const Real theta2 = 2.0 * std::numbers::pi * unitUniform(generator);
    const Real r1 = std::sqrt(1.0 - u1);
    const Real r2 = std::sqrt(u1);
    // glm's constructor takes w first
    return Quat(r2 * std::cos(theta2), r1 * std::sin(theta1), r1 * std::cos(theta1),
                r2 * std::sin(theta2));
}

/// Uniform on the unit sphere (Archimedes: z uniform in [-1, 1], azimuth uniform).
Vec3 uniformDirection(std::mt19937_64& generator)
{
    const Real z = 2.0 * unitUniform(generator) - 1.0;
    const Real azimuth = 2.0 * std::numbers::pi * unitUniform(generator);
    const Real radius = std::sqrt(std::max(0.0, 1.0 - z * z));
    return Vec3(radius * std::cos(azimuth), z, radius * std::sin(azimuth));
}

} // namespace

std::uint64_t throwSeed(std::uint64_t seed, std::uint64_t index)
{
    return splitmix64(splitmix64(seed) + index);
}

ThrowState drawThrow(const Scenario& scenario, std::uint64_t seed, std::uint64_t index)
{
    if (!scenario.throwSpec || scenario.bodies.size() != 1 || !scenario.ground) {
        throw std::invalid_argument("drawThrow: the scenario has no valid [throw] table");
    }
    const ThrowSpec& spec = *scenario.throwSpec;
    std::mt19937_64 generator(throwSeed(seed, index));

    // a fixed order of draws (docs/dice.md): orientation, horizontal direction and speed,
    // vertical speed, spin axis and magnitude, height; the orientation's three are drawn even
    // when the body's own orientation is used, so the others do not depend on that choice
    ThrowState state;
    const Quat drawn = uniformRotation(generator);
    state.orientation = spec.orientation == ThrowOrientation::Random
                            ? drawn
                            : scenario.bodies.front().def.orientation;
    const Real heading = 2.0 * std::numbers::pi * unitUniform(generator);
    const Real speed = uniformIn(generator, spec.speed);
    const Real verticalSpeed = uniformIn(generator, spec.verticalSpeed);
    state.velocity = Vec3(speed * std::cos(heading), verticalSpeed, speed * std::sin(heading));
    const Vec3 axis = uniformDirection(generator);
    state.angularVelocity = uniformIn(generator, spec.angularSpeed) * axis;
    const Real height = uniformIn(generator, spec.height);
    state.position = Vec3(0.0, scenario.ground->height + height, 0.0);
    return state;
}

} // namespace tumble::scenario
