// Text for scenario error messages: numbers and vectors, node descriptions, unknown-key hints.
#pragma once

#include "tumble/math.hpp"

#include <toml++/toml.h>

#include <span>
#include <string>
#include <string_view>

namespace tumble::scenario::detail {

/// Shortest text that reads back as the same double ("0.1", "-1", "nan").
std::string formatReal(Real value);
/// "[1, 2, 3]".
std::string formatVec3(const Vec3& value);

/// Levenshtein distance between two short strings.
int editDistance(std::string_view a, std::string_view b);

/// "unknown key 'x'" plus a suggestion (edit distance <= 2) or the list of known keys.
std::string unknownKeyProblem(std::string_view key, std::span<const std::string_view> known);

/// What a node is, for "expected ..., got ..." messages: "a string (\"abc\")", "an integer",
/// "an array of 2 values".
std::string describeNode(const toml::node& node);

} // namespace tumble::scenario::detail
