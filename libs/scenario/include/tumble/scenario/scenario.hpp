// Scenario: a scene file turned into plain data, and a World built from it.
#pragma once

#include "tumble/body_id.hpp"
#include "tumble/math.hpp"
#include "tumble/scenario/throw_spec.hpp"
#include "tumble/shape.hpp"
#include "tumble/world.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace tumble::scenario {

/// Where a value came from: a file and line, or a --set override.
struct SourceLocation {
    std::string file;
    /// 1-based line; 0 when unknown (a missing file, an override).
    int line = 0;
};

/// A bad scenario: what() is one line "FILE:LINE: KEY: problem" (":LINE" left out when unknown).
class ScenarioError : public std::runtime_error {
public:
    ScenarioError(SourceLocation where, std::string key, const std::string& problem);

    [[nodiscard]] const SourceLocation& where() const { return m_where; }
    [[nodiscard]] const std::string& key() const { return m_key; }
    /// The message without its location and key.
    [[nodiscard]] const std::string& problem() const { return m_problem; }

private:
    SourceLocation m_where;
    std::string m_key;
    std::string m_problem;
};

/// One [[body]] entry.
struct BodySpec {
    /// Unique name; "body<i>" (1-based) when the file gives none.
    std::string name;
    BodyDef def{};
    SourceLocation where{};
};

/// One [[spawn]] entry: `count` bodies on a square grid in x and z, each with a height, an
/// orientation and a spin drawn from one seeded stream (docs/scenario-format.md, [[spawn]]).
struct SpawnSpec {
    std::size_t count = 0;
    std::uint64_t seed = 0;
    /// Distance between neighbouring grid points, m.
    Real spacing = 0.0;
    /// Size, mass, velocity and material of every body; position, orientation and angular
    /// velocity are drawn.
    BodyDef body{};
    /// Centre-of-mass height above the ground, drawn uniformly in [low, high], m.
    Real heightLow = 0.0;
    Real heightHigh = 0.0;
    /// A uniformly random rotation, or `body.orientation` for every body.
    bool randomOrientation = false;
    /// Angular speed drawn uniformly in [low, high] about a uniformly random axis, rad/s.
    Real angularSpeedLow = 0.0;
    Real angularSpeedHigh = 0.0;
    SourceLocation where{};
};

/// The bodies a SpawnSpec places over `groundHeight`, named "<prefix><k>" (k from 1). The same
/// spec gives the same bodies on every machine: std::mt19937_64 seeded with `seed`, drawn in the
/// order height, orientation (3 numbers, when random), angular speed, axis (2) for each body
/// in turn, each number mapped to [0, 1) by our own rule (RandomDraws).
std::vector<BodySpec> spawnBodies(const SpawnSpec& spawn, Real groundHeight,
                                  std::string_view prefix);

/// One [[impulse]] entry: either an impulse at an offset, or a target the runner solves for.
struct ImpulseSpec {
    /// Simulated time at which it is applied, s (>= 0).
    Real at = 0.0;
    /// Name of the body it acts on.
    std::string body;
    /// Impulse (N s) and offset (point minus centre of mass, world axes, m) when given directly.
    std::optional<Vec3> impulse;
    std::optional<Vec3> offset;
    /// Target velocity and angular velocity when the impulse is to be solved for.
    std::optional<Vec3> targetVelocity;
    std::optional<Vec3> targetAngularVelocity;
    /// "impulse[i]" (0-based, file order), used in messages.
    std::string label;
    SourceLocation where{};

    [[nodiscard]] bool isTarget() const { return targetVelocity.has_value(); }
};

/// A whole scene: world settings, run parameters, ground, bodies and scheduled impulses.
struct Scenario {
    std::string sourceName;
    WorldSettings settings{};
    /// Fixed time step, s. Default 1/240.
    Real dt = 1.0 / 240.0;
    /// How long `tumble run` simulates, s. Default 10.
    Real duration = 10.0;
    /// The ground plane; none when the file has no [ground] table.
    std::optional<Plane> ground;
    /// The ground's own material ([ground] elasticity, friction, static_friction); none when it
    /// gives none, and its contacts take the dynamic body's.
    std::optional<Material> groundMaterial;
    /// The [[plane]] half-spaces, in file order.
    std::vector<StaticPlane> planes;
    /// The [[body]] entries, then the bodies of each [[spawn]] (named spawn<s>_<k>, 1-based).
    std::vector<BodySpec> bodies;
    std::vector<SpawnSpec> spawns;
    /// Sorted by `at` (stable, so entries at the same time keep file order).
    std::vector<ImpulseSpec> impulses;
    /// The [throw] table of a dice scenario (`tumble throw`); none when the file has none.
    /// `tumble run` ignores it and runs the body as the file gives it.
    std::optional<ThrowSpec> throwSpec;
};

/// Reads and validates a scenario file. `overrides` are "KEY=VALUE" strings (`world.dt=0.001`,
/// `rb.elasticity=0.7`, `ground.height=1`) applied before validation. Throws ScenarioError.
Scenario loadScenario(const std::filesystem::path& path, std::span<const std::string> overrides = {});

/// Same, from text already in memory; `sourceName` is used in messages.
Scenario parseScenario(std::string_view text, std::string_view sourceName,
                       std::span<const std::string> overrides = {});

/// A World holding the scenario's ground, planes and bodies, and the ids in BodySpec order.
struct BuiltWorld {
    World world;
    std::vector<BodyId> bodies;
};

BuiltWorld buildWorld(const Scenario& scenario);

} // namespace tumble::scenario
