// The [throw] table of a dice scenario, checked against the die and the world and turned into a
// ThrowSpec.
#pragma once

#include "toml_reader.hpp"

#include "tumble/scenario/scenario.hpp"

#include <toml++/toml.h>

namespace tumble::scenario::detail {

/// Sets scenario.throwSpec when `root` has a [throw] table. Call after the world, ground, bodies
/// and impulses are read: a throw needs a ground and exactly one body, and its ranges are
/// checked against that body's size and the world's dt.
void readThrow(const TomlReader& reader, const toml::table& root, Scenario& scenario);

} // namespace tumble::scenario::detail
