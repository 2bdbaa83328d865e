// --set overrides: "KEY=VALUE" strings applied to a parsed scenario table before it is validated.
#pragma once

#include <toml++/toml.h>

#include <span>
#include <string>

namespace tumble::scenario::detail {

/// Applies each override in order (a later one wins). KEY is `world.<key>`, `ground.height`,
/// `<body name>.<key>` (also `body<i>` for an unnamed body, and `body.<key>` when there is one
/// body) or `impulse[<i>].<key>`; VALUE is a TOML value, or a bare word taken as a string.
/// Throws ScenarioError located at "--set" for a malformed override or an unknown target.
void applyOverrides(toml::table& root, std::span<const std::string> overrides);

} // namespace tumble::scenario::detail
