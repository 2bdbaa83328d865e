// Drawing the dice of a throw: one RandomDraws stream per (seed, throw, die), and for a cluster
// release one more for the hand; a die that would start inside static geometry or an earlier
// die is drawn again from its own stream (docs/dice.md).
#include "tumble/scenario/throw_dice.hpp"

#include "tumble/scenario/random_draws.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace tumble::scenario {

namespace {

/// The hand's stream of a cluster release: an index no die has.
constexpr std::uint64_t kHandStream = std::uint64_t{1} << 63U;

/// The motion of a release: a horizontal heading and speed, and a vertical speed.
Vec3 drawVelocity(RandomDraws& draws, const ThrowSpec& spec)
{
    const Real heading = draws.uniform(spec.heading.min, spec.heading.max);
    const Real speed = draws.uniform(spec.speed.min, spec.speed.max);
    const Real verticalSpeed = draws.uniform(spec.verticalSpeed.min, spec.verticalSpeed.max);
    return {speed * std::cos(heading), verticalSpeed, speed * std::sin(heading)};
}

/// A release point: in the region, or above the origin at a drawn height over the ground.
Vec3 drawReleasePoint(RandomDraws& draws, const Scenario& scenario)
{
    const ThrowSpec& spec = *scenario.throwSpec;
    if (spec.region) {
        const ThrowRegion& region = *spec.region;
        const Real x = draws.uniform(region.min.x, region.max.x);
        const Real y = draws.uniform(region.min.y, region.max.y);
        const Real z = draws.uniform(region.min.z, region.max.z);
        return {x, y, z};
    }
    const Real height = draws.uniform(spec.height.min, spec.height.max);
    return {0.0, scenario.ground->height + height, 0.0};
}

/// One die on its own, in drawThrow's order: orientation, velocity, spin axis and magnitude,
/// release point.
ThrowState drawEach(RandomDraws& draws, const Scenario& scenario, const BodyDef& die)
{
    const ThrowSpec& spec = *scenario.throwSpec;
    ThrowState state;
    const Quat drawn = draws.rotation();
    state.orientation = spec.orientation == ThrowOrientation::Random ? drawn : die.orientation;
    state.velocity = drawVelocity(draws, spec);
    const Vec3 axis = draws.direction();
    state.angularVelocity = draws.uniform(spec.angularSpeed.min, spec.angularSpeed.max) * axis;
    state.position = drawReleasePoint(draws, scenario);
    return state;
}

/// One die of a cluster: the hand's point and velocity, its own orientation and spin, and an
/// offset uniform in the ball of radius clusterRadius.
ThrowState drawInHand(RandomDraws& draws, const Scenario& scenario, const BodyDef& die,
                      const ThrowState& hand)
{
    const ThrowSpec& spec = *scenario.throwSpec;
    ThrowState state = hand;
    const Quat drawn = draws.rotation();
    state.orientation = spec.orientation == ThrowOrientation::Random ? drawn : die.orientation;
    const Vec3 axis = draws.direction();
    state.angularVelocity = draws.uniform(spec.angularSpeed.min, spec.angularSpeed.max) * axis;
    const Vec3 direction = draws.direction();
    state.position += spec.clusterRadius * std::cbrt(draws.unit()) * direction;
    return state;
}

/// Whether a die at `state` overlaps the ground, a plane, a static body or an earlier die.
bool overlaps(const Scenario& scenario, const std::vector<std::size_t>& dice, std::size_t k,
              std::span<const ThrowState> placed, const ThrowState& state)
{
    const Vec3 half = scenario.bodies[dice[k]].def.shape.halfExtents();
    const Transform pose{state.position, normalizedOrientation(state.orientation)};
    if (scenario.ground &&
        cuboidHalfSpaceDepth(pose, half, StaticPlane{Vec3(0.0, scenario.ground->height, 0.0),
                                                     Plane::normal(), {}}) > 0.0) {
        return true;
    }
    for (const StaticPlane& plane : scenario.planes) {
        if (cuboidHalfSpaceDepth(pose, half, plane) > 0.0) {
            return true;
        }
    }
    for (const BodySpec& body : scenario.bodies) {
        if (body.def.motion == BodyMotion::Static &&
            cuboidOverlapDepth(pose, half, {body.def.position, normalizedOrientation(body.def.orientation)},
                               body.def.shape.halfExtents()) > 0.0) {
            return true;
        }
    }
    for (std::size_t j = 0; j < k; ++j) {
        const ThrowState& other = placed[j];
        if (cuboidOverlapDepth(pose, half,
                               {other.position, normalizedOrientation(other.orientation)},
                               scenario.bodies[dice[j]].def.shape.halfExtents()) > 0.0) {
            return true;
        }
    }
    return false;
}

} // namespace

std::vector<std::size_t> diceOf(const Scenario& scenario)
{
    std::vector<std::size_t> dice;
    for (std::size_t i = 0; i < scenario.bodies.size(); ++i) {
        if (scenario.bodies[i].def.motion == BodyMotion::Dynamic) {
            dice.push_back(i);
        }
    }
    return dice;
}

std::uint64_t dieSeed(std::uint64_t seed, std::uint64_t index, std::size_t die)
{
    const std::uint64_t first = throwSeed(seed, index);
    return die == 0 ? first : throwSeed(first, die);
}

std::vector<ThrowState> drawDice(const Scenario& scenario, std::uint64_t seed, std::uint64_t index,
                                 std::vector<bool>* placed)
{
    if (!scenario.throwSpec) {
        throw std::invalid_argument("drawDice: the scenario has no [throw] table");
    }
    const ThrowSpec& spec = *scenario.throwSpec;
    const std::vector<std::size_t> dice = diceOf(scenario);
    ThrowState hand;
    if (spec.release == ThrowRelease::Cluster) {
        RandomDraws draws(throwSeed(throwSeed(seed, index), kHandStream));
        hand.velocity = drawVelocity(draws, spec);
        hand.position = drawReleasePoint(draws, scenario);
    }
    std::vector<ThrowState> states(dice.size());
    if (placed != nullptr) {
        placed->assign(dice.size(), true);
    }
    for (std::size_t k = 0; k < dice.size(); ++k) {
        const BodyDef& die = scenario.bodies[dice[k]].def;
        RandomDraws draws(dieSeed(seed, index, k));
        // redraws continue the die's own stream, so they are as deterministic as the first draw
        int attempt = 0;
        do {
            states[k] = spec.release == ThrowRelease::Cluster
                            ? drawInHand(draws, scenario, die, hand)
                            : drawEach(draws, scenario, die);
        } while (overlaps(scenario, dice, k, states, states[k]) &&
                 ++attempt < kPlacementAttempts);
        if (attempt == kPlacementAttempts && placed != nullptr) {
            (*placed)[k] = false;
        }
    }
    return states;
}

} // namespace tumble::scenario
