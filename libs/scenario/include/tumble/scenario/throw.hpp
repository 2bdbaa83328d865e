// The throw model of `tumble throw`: draw the initial state of throw i of a dice scenario from
// its [throw] ranges, run it to rest, and write it as an ordinary scenario file
// (docs/dice.md).
#pragma once

#include "tumble/math.hpp"
#include "tumble/scenario/scenario.hpp"
#include "tumble/shape.hpp"

#include <cstdint>
#include <string>

namespace tumble::scenario {

/// The drawn initial state of one throw, world frame.
struct ThrowState {
    /// Centre of mass, m: above the origin at the drawn height over the ground.
    Vec3 position{0.0};
    /// Body-to-world rotation as drawn (unit up to rounding); the die starts at
    /// normalizedOrientation(orientation), which is what a scenario file holding it loads as.
    Quat orientation{1.0, 0.0, 0.0, 0.0};
    /// m/s.
    Vec3 velocity{0.0};
    /// rad/s.
    Vec3 angularVelocity{0.0};
};

/// How a throw ended.
struct ThrowOutcome {
    /// Whether the die came to rest (World's RestEvent) before the spec's maxTime.
    bool settled = false;
    /// The face on the ground at rest (meaningful when settled).
    CuboidFace faceDown = CuboidFace::MinusY;
    /// When the die came to rest (RestEvent::time), s; 0 when unsettled.
    Real restTime = 0.0;
};

/// The seed of throw `index`'s generator: splitmix64(splitmix64(seed) + index), so every
/// (seed, index) pair has its own stream whatever order, thread or MPI rank runs it.
std::uint64_t throwSeed(std::uint64_t seed, std::uint64_t index);

/// The initial state of throw `index` for a scenario with a [throw] table (throws
/// std::invalid_argument without one). Deterministic in (seed, index): std::mt19937_64 seeded
/// with throwSeed, mapped to [0, 1) by its top 53 bits (docs/dice.md gives the order of draws).
ThrowState drawThrow(const Scenario& scenario, std::uint64_t seed, std::uint64_t index);

/// Runs one throw in its own World, exactly as `tumble run` would run throwScenario(scenario,
/// state): the same world, the same sequence of step lengths. Stops at the RestEvent or at the
/// spec's maxTime.
ThrowOutcome runThrow(const Scenario& scenario, const ThrowState& state);

/// The scenario of one throw: the body starts in `state`, the duration is the spec's maxTime,
/// and the [throw] table is gone.
Scenario throwScenario(const Scenario& scenario, const ThrowState& state);

/// throwScenario as TOML text that loadScenario reads back to the same bits (every number with
/// %.17g); `comment` (one or more lines) opens the file as # comments.
std::string throwScenarioToml(const Scenario& scenario, const ThrowState& state,
                              const std::string& comment);

/// The rotation a file's quaternion [w, x, y, z] loads as: q / |q|. The loader and runThrow
/// share it so a replayed throw starts bit for bit where the throw did.
Quat normalizedOrientation(const Quat& q);

} // namespace tumble::scenario
