// Throws of several dice at once (docs/dice.md): each die's state drawn from (seed, throw, die),
// the throw run until every die is at rest, each die's face read against the surface it rests
// on, and the throw written as an ordinary scenario file.
#pragma once

#include "tumble/body_id.hpp"
#include "tumble/math.hpp"
#include "tumble/scenario/scenario.hpp"
#include "tumble/scenario/throw.hpp"
#include "tumble/shape.hpp"
#include "tumble/world.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace tumble::scenario {

/// How one die of a throw ended. Plain bytes, so MPI ranks send blocks of them as they are.
struct DieOutcome {
    /// 1 when every die of the throw came to rest before maxTime.
    std::uint8_t settled = 0;
    /// 1 when no face lies within kCockedDegrees of the plane it rests on.
    std::uint8_t cocked = 0;
    /// The CuboidFace nearest the support (meaningful when settled).
    std::uint8_t face = static_cast<std::uint8_t>(CuboidFace::MinusY);
    /// 1 when the die could not be placed clear of the others (kPlacementAttempts draws).
    std::uint8_t unplaced = 0;
    /// The die's last RestEvent time, s; 0 when unsettled.
    Real restTime = 0.0;
};

/// A die at rest whose face down is tilted more than this from its support's plane is cocked.
constexpr Real kCockedDegrees = 5.0;
/// Draws of one die's state before a throw is given up as unplaceable.
constexpr int kPlacementAttempts = 64;

/// The indices into scenario.bodies of the dice: the dynamic bodies, in file order.
std::vector<std::size_t> diceOf(const Scenario& scenario);

/// The seed of die `die`'s generator in throw `index`: throwSeed(seed, index) for die 0 (so a
/// single die draws as it always has), splitmix64(throwSeed(seed, index) + die) for the others.
std::uint64_t dieSeed(std::uint64_t seed, std::uint64_t index, std::size_t die);

/// Every die's initial state in throw `index`, in diceOf order. Each die is drawn clear of the
/// static geometry, the ground and the dice before it: a die that overlaps is drawn again from
/// its own stream, at most kPlacementAttempts times (placed[k] is false when it never fit).
/// Throws std::invalid_argument without a [throw] table.
std::vector<ThrowState> drawDice(const Scenario& scenario, std::uint64_t seed, std::uint64_t index,
                                 std::vector<bool>* placed = nullptr);

/// The scenario of one throw: the dice start in `states`, the duration is maxTime, the [throw]
/// table is gone. buildWorld of it is the world the throw runs in.
Scenario diceScenario(const Scenario& scenario, std::span<const ThrowState> states);

/// Runs an already built world for at most maxTime with `tumble run`'s steps until every one of
/// `dice` is at rest, and reads each die's face against its support. outcomes.size() ==
/// dice.size().
void runDiceWorld(World& world, std::span<const BodyId> dice, Real maxTime, Real dt,
                  std::span<DieOutcome> outcomes);

/// drawDice + diceScenario + runDiceWorld: throw `index` into outcomes (one per die).
void runDiceThrow(const Scenario& scenario, std::uint64_t seed, std::uint64_t index,
                  std::span<DieOutcome> outcomes);

/// The face of a die at rest and whether it is cocked: the support is the touching surface
/// (ground, plane, static body or other die) whose outward normal is nearest to up.
DieOutcome readDieAtRest(const World& world, BodyId die);

/// diceScenario as TOML text that loadScenario reads back to the same bits; `comment` opens the
/// file as # comments.
std::string diceScenarioToml(const Scenario& scenario, std::span<const ThrowState> states,
                             const std::string& comment);

} // namespace tumble::scenario
