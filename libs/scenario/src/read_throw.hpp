// The [throw] table of a dice scenario, checked against the die and the world and turned into a
// ThrowSpec.
#pragma once

#include "toml_reader.hpp"

#include "tumble/scenario/scenario.hpp"

#include <toml++/toml.h>

#include <cstddef>

namespace tumble::scenario::detail {

/// The dice of a [throw] scenario: its dynamic bodies.
std::size_t throwDiceCount(const Scenario& scenario);
/// Half the diagonal of the largest die, m (0 without dice).
Real largestHalfDiagonal(const Scenario& scenario);
/// Reads release, cluster_radius and region into `spec`.
void readRelease(const TomlReader& reader, const toml::table& table, ThrowSpec& spec);

/// Sets scenario.throwSpec when `root` has a [throw] table. Call after the world, ground, bodies
/// and impulses are read: a throw needs at least one
/// dynamic body (a die) and, without a region, a ground, and its ranges are
/// checked against that body's size and the world's dt.
void readThrow(const TomlReader& reader, const toml::table& root, Scenario& scenario);

} // namespace tumble::scenario::detail
