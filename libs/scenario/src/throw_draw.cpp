// Drawing a throw's initial state: one RandomDraws stream (std::mt19937_64 with our own mapping
// to [0, 1), Shoemake's rotation, uniform directions) per (seed, index) (docs/dice.md).
#include "tumble/scenario/throw.hpp"

#include "tumble/scenario/random_draws.hpp"

#include <cmath>
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

Real uniformIn(RandomDraws& draws, const DrawRange& range)
{
    return draws.uniform(range.min, range.max);
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
    RandomDraws generator(throwSeed(seed, index));

    // a fixed order of draws (docs/dice.md): orientation, horizontal direction and speed,
    // vertical speed, spin axis and magnitude, height; the orientation's three are drawn even
    // when the body's own orientation is used, so the others do not depend on that choice
    ThrowState state;
    const Quat drawn = generator.rotation();
    state.orientation = spec.orientation == ThrowOrientation::Random
                            ? drawn
                            : scenario.bodies.front().def.orientation;
    // the default heading [0, 2 pi] gives 2 pi u exactly, as before headings could be given
    const Real heading = uniformIn(generator, spec.heading);
    const Real speed = uniformIn(generator, spec.speed);
    const Real verticalSpeed = uniformIn(generator, spec.verticalSpeed);
    state.velocity = Vec3(speed * std::cos(heading), verticalSpeed, speed * std::sin(heading));
    const Vec3 axis = generator.direction();
    state.angularVelocity = uniformIn(generator, spec.angularSpeed) * axis;
    const Real height = uniformIn(generator, spec.height);
    state.position = Vec3(0.0, scenario.ground->height + height, 0.0);
    return state;
}

} // namespace tumble::scenario
