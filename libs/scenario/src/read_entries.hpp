// The [[body]] and [[impulse]] arrays of a scenario file, checked and turned into specs.
#pragma once

#include "toml_reader.hpp"

#include "tumble/scenario/scenario.hpp"

#include <toml++/toml.h>

#include <optional>
#include <span>
#include <string>

namespace tumble::scenario::detail {

/// The array of tables `name` ([[body]], [[impulse]], [[spawn]]), or null when absent.
const toml::array* arrayOfTables(const TomlReader& reader, const toml::table& root,
                                 std::string_view name);

/// Fails unless |angularVelocity| is within the valid range and turns the body by at most the
/// valid angle in one step of length dt.
void checkAngularSpeed(const TomlReader& reader, const toml::node& node, const std::string& key,
                       const Vec3& angularVelocity, Real dt, const std::string& context);

/// `size` or `scale` (not both) of `table` into the cuboid's full extents, range-checked.
void readShape(const TomlReader& reader, const toml::table& table, const std::string& key,
               const std::string& context, BodyDef& def);

/// elasticity, friction and static_friction of `table` into `material`.
void readMaterial(const TomlReader& reader, const toml::table& table, const std::string& key,
                  const std::string& context, Material& material);

/// Appends one BodySpec per [[body]] (names must be unique).
void readBodies(const TomlReader& reader, const toml::table& root, Scenario& scenario);

/// Fails when a dynamic body starts deeper than the contact tolerance inside a [[plane]].
void checkClearOfStaticPlanes(const TomlReader& reader, const toml::table& table,
                              const BodySpec& spec, const Scenario& scenario,
                              const std::string& key);

/// Fails when a body of a [[spawn]] (the entry `table`, named `key`) starts deeper than the
/// contact tolerance inside a [[plane]], a body read before (a [[body]] or an earlier spawn's).
void checkSpawnClearance(const TomlReader& reader, const toml::table& table,
                         const std::string& key, const Scenario& scenario,
                         std::span<const BodySpec> spawned);

/// Fails when the body overlaps a body read before it by more than the contact tolerance, unless
/// both are static.
void checkClearOfBodies(const TomlReader& reader, const toml::table& table, const BodySpec& spec,
                        const Scenario& scenario, const std::string& key);

/// Appends one StaticPlane per [[plane]] (point and normal required, normal nonzero, normalised;
/// a material when the entry gives one).
void readPlanes(const TomlReader& reader, const toml::table& root, Scenario& scenario);

/// The material keys of `table`, or none when it gives none.
std::optional<Material> readOptionalMaterial(const TomlReader& reader, const toml::table& table,
                                             const std::string& key);

/// Appends one ImpulseSpec per [[impulse]] (each naming a body already read) and sorts them by
/// `at`, keeping file order for equal times.
void readImpulses(const TomlReader& reader, const toml::table& root, Scenario& scenario);

} // namespace tumble::scenario::detail

namespace tumble::scenario::detail {

/// Appends one SpawnSpec per [[spawn]] and the bodies it places to scenario.bodies; the world
/// and ground must be read already (the heights are above the ground, the spin is checked
/// against dt).
void readSpawns(const TomlReader& reader, const toml::table& root, Scenario& scenario);

} // namespace tumble::scenario::detail
