// The shortest text that reads back as the same double, as std::to_chars(first, last, value)
// writes it, for standard libraries without floating-point to_chars (Emscripten's libc++ 14,
// which the web build uses); messages.cpp calls std::to_chars where it exists.
#pragma once

#include <string>

namespace tumble::scenario::detail {

/// The fewest significant digits that round-trip through strtod, correctly rounded, in fixed
/// notation unless scientific is shorter (the format of to_chars without a chars_format).
/// `value` is finite.
std::string shortestReal(double value);

} // namespace tumble::scenario::detail
