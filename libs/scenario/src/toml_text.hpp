// Numbers, strings and the [world] table as TOML text that loadScenario reads back to the same
// bits: what `tumble throw --replay` writes.
#pragma once

#include "tumble/math.hpp"
#include "tumble/scenario/scenario.hpp"

#include <ostream>
#include <string>

namespace tumble::scenario::detail {

/// %.17g: enough digits for every double to read back as itself.
std::string exact(Real value);
/// [x, y, z], each with exact().
std::string exact(const Vec3& v);
/// [w, x, y, z], each with exact().
std::string exact(const Quat& q);
/// A TOML basic string: quotes, backslashes and control characters escaped.
std::string tomlString(const std::string& text);

/// "\n[world]\n" and every world setting, defaults too (so the file does not depend on today's
/// defaults), with `duration`.
void writeWorldToml(std::ostream& out, const Scenario& scenario, Real duration);

/// `comment`'s lines as # comments.
void writeCommentToml(std::ostream& out, const std::string& comment);

} // namespace tumble::scenario::detail
