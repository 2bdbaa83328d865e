// TomlReader: typed, checked reads of toml++ nodes that fail with a ScenarioError naming the file,
// line and key (or the --set override a value came from).
#pragma once

#include "valid_ranges.hpp"

#include "tumble/math.hpp"
#include "tumble/scenario/scenario.hpp"

#include <toml++/toml.h>

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <utility>

namespace tumble::scenario::detail {

/// Source path given to toml::parse for a --set value, so that every node it produces (and every
/// error about it) can be traced back to the override: "--set\n<override key>\n<file key>".
std::string overrideSourcePath(std::string_view overrideKey, std::string_view fileKey);

/// Calls `read(node)` when `table` has the key `name`.
template <typename Read>
void ifPresent(const toml::table& table, std::string_view name, Read&& read)
{
    if (const toml::node* node = table.get(name)) {
        std::forward<Read>(read)(*node);
    }
}

/// Every read takes the value's dotted key in file terms ("body[0].mass") for its messages; a
/// range check may add `context` to the end of the message (" (body \"rb\")").
class TomlReader {
public:
    explicit TomlReader(std::string sourceName) : m_sourceName(std::move(sourceName)) {}

    [[nodiscard]] const std::string& sourceName() const { return m_sourceName; }

    /// The error for a value at `source`: located at its file and line, or at "--set" with the
    /// override's own key when the value came from an override.
    [[nodiscard]] ScenarioError error(const toml::source_region& source, std::string key,
                                      const std::string& problem) const;
    [[noreturn]] void fail(const toml::node& node, std::string key,
                           const std::string& problem) const;
    [[nodiscard]] SourceLocation locate(const toml::node& node) const;

    /// Fails on the first key (in file order) of `table` that is not in `known`.
    void checkKeys(const toml::table& table, std::string_view prefix,
                   std::span<const std::string_view> known) const;

    /// The node as a table, failing when it is something else ("expected <expected>").
    [[nodiscard]] const toml::table& table(const toml::node& node, const std::string& key,
                                           std::string_view expected) const;
    /// A finite number (integer or floating point).
    [[nodiscard]] Real real(const toml::node& node, const std::string& key) const;
    /// A finite number > 0.
    [[nodiscard]] Real positive(const toml::node& node, const std::string& key,
                                const std::string& context = {}) const;
    /// A finite number >= 0.
    [[nodiscard]] Real nonNegative(const toml::node& node, const std::string& key,
                                   const std::string& context = {}) const;
    /// An array of exactly 3 finite numbers.
    [[nodiscard]] Vec3 vec3(const toml::node& node, const std::string& key) const;
    /// An array of 3 finite numbers, each > 0 (a size or a scale).
    [[nodiscard]] Vec3 positiveVec3(const toml::node& node, const std::string& key,
                                    const std::string& context = {}) const;
    [[nodiscard]] long long integer(const toml::node& node, const std::string& key) const;
    [[nodiscard]] bool boolean(const toml::node& node, const std::string& key) const;
    [[nodiscard]] std::string string(const toml::node& node, const std::string& key) const;
    /// A string that is one of `allowed`, as its index; the message lists the allowed values.
    [[nodiscard]] std::size_t choice(const toml::node& node, const std::string& key,
                                     std::span<const std::string_view> allowed) const;
    /// Fails unless `range.low <= value <= range.high` ("must be between LOW and HIGH UNIT" or,
    /// for a range starting at 0, "must be at most HIGH UNIT"). `what` goes before "must" ("the
    /// length " for a vector).
    void checkRange(const toml::node& node, const std::string& key, Real value,
                    const ValidRange& range, std::string_view what = {},
                    const std::string& context = {}) const;
    /// [w, x, y, z] within 1e-6 of unit length (normalised), or { axis = [x, y, z], degrees = a }.
    [[nodiscard]] Quat orientation(const toml::node& node, const std::string& key) const;

private:
    std::string m_sourceName;
};

} // namespace tumble::scenario::detail
