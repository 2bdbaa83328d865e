// The [[body]] and [[impulse]] arrays of a scenario file, checked and turned into specs.
#pragma once

#include "toml_reader.hpp"

#include "tumble/scenario/scenario.hpp"

#include <toml++/toml.h>

namespace tumble::scenario::detail {

/// Appends one BodySpec per [[body]] (at least one is required; names must be unique).
void readBodies(const TomlReader& reader, const toml::table& root, Scenario& scenario);

/// Appends one ImpulseSpec per [[impulse]] (each naming a body already read) and sorts them by
/// `at`, keeping file order for equal times.
void readImpulses(const TomlReader& reader, const toml::table& root, Scenario& scenario);

} // namespace tumble::scenario::detail
