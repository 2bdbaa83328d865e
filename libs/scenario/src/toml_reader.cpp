// TomlReader: typed, checked reads of toml++ nodes that fail with a ScenarioError naming the file,
// line and key (or the --set override a value came from).
#include "toml_reader.hpp"

#include "messages.hpp"
#include "schema.hpp"
#include "vector_length.hpp"

#include "tumble/scenario/throw.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace tumble::scenario::detail {

namespace {

constexpr std::string_view kOverridePrefix = "--set\n";
constexpr Real kUnitQuaternionTolerance = 1e-6;

/// The override key and the file key a --set source path carries, or nothing.
bool parseOverridePath(const toml::source_region& source, std::string& overrideKey,
                       std::string& fileKey)
{
    if (!source.path || !source.path->starts_with(kOverridePrefix)) {
        return false;
    }
    const std::string_view rest = std::string_view(*source.path).substr(kOverridePrefix.size());
    const std::size_t newline = rest.find('\n');
    overrideKey = std::string(rest.substr(0, newline));
    fileKey =
        newline == std::string_view::npos ? std::string() : std::string(rest.substr(newline + 1));
    return true;
}

} // namespace

std::string overrideSourcePath(std::string_view overrideKey, std::string_view fileKey)
{
    std::string path(kOverridePrefix);
    path += overrideKey;
    path += '\n';
    path += fileKey;
    return path;
}

ScenarioError TomlReader::error(const toml::source_region& source, std::string key,
                                const std::string& problem) const
{
    std::string overrideKey;
    std::string fileKey;
    if (parseOverridePath(source, overrideKey, fileKey)) {
        // A value from --set: report it under the override's own key ("rb.mass"), keeping any
        // tail below the overridden key ("rb.orientation" + ".axis").
        std::string reported = overrideKey;
        if (!fileKey.empty() && key.starts_with(fileKey)) {
            reported += key.substr(fileKey.size());
        }
        return ScenarioError(SourceLocation{"--set", 0}, std::move(reported), problem);
    }
    return ScenarioError(SourceLocation{m_sourceName, static_cast<int>(source.begin.line)},
                         std::move(key), problem);
}

void TomlReader::fail(const toml::node& node, std::string key, const std::string& problem) const
{
    throw error(node.source(), std::move(key), problem);
}

SourceLocation TomlReader::locate(const toml::node& node) const
{
    std::string overrideKey;
    std::string fileKey;
    if (parseOverridePath(node.source(), overrideKey, fileKey)) {
        return SourceLocation{"--set", 0};
    }
    return SourceLocation{m_sourceName, static_cast<int>(node.source().begin.line)};
}

void TomlReader::checkKeys(const toml::table& table, std::string_view prefix,
                           std::span<const std::string_view> known) const
{
    // toml++ keeps keys sorted by name; report the unknown key that comes first in the file.
    const toml::key* first = nullptr;
    for (const auto& [key, value] : table) {
        const bool isKnown = std::find(known.begin(), known.end(), key.str()) != known.end();
        if (!isKnown && (first == nullptr || key.source().begin < first->source().begin)) {
            first = &key;
        }
    }
    if (first != nullptr) {
        std::string dotted = prefix.empty() ? std::string() : std::string(prefix) + ".";
        dotted += first->str();
        throw error(first->source(), std::move(dotted), unknownKeyProblem(first->str(), known));
    }
}

const toml::table& TomlReader::table(const toml::node& node, const std::string& key,
                                     std::string_view expected) const
{
    if (const toml::table* result = node.as_table()) {
        return *result;
    }
    fail(node, key, "expected " + std::string(expected) + ", got " + describeNode(node));
}

Real TomlReader::real(const toml::node& node, const std::string& key) const
{
    Real value = 0.0;
    if (const auto* integer = node.as_integer()) {
        value = static_cast<Real>(integer->get());
    } else if (const auto* floating = node.as_floating_point()) {
        value = floating->get();
    } else {
        fail(node, key, "expected a number, got " + describeNode(node));
    }
    if (!std::isfinite(value)) {
        fail(node, key, "must be finite, got " + formatReal(value));
    }
    return value;
}

Real TomlReader::positive(const toml::node& node, const std::string& key,
                          const std::string& context) const
{
    const Real value = real(node, key);
    if (!(value > 0.0)) {
        fail(node, key, "must be > 0, got " + formatReal(value) + context);
    }
    return value;
}

Real TomlReader::nonNegative(const toml::node& node, const std::string& key,
                             const std::string& context) const
{
    const Real value = real(node, key);
    if (!(value >= 0.0)) {
        fail(node, key, "must be >= 0, got " + formatReal(value) + context);
    }
    return value;
}

void TomlReader::checkRange(const toml::node& node, const std::string& key, Real value,
                            const ValidRange& range, std::string_view what,
                            const std::string& context) const
{
    if (value >= range.low && value <= range.high) {
        return;
    }
    // Built by appending: GCC 12 warns (-Wrestrict, falsely) on a chain of operator+ here.
    std::string problem(what);
    problem += "must be ";
    if (range.low == 0.0) {
        problem += "at most ";
    } else {
        problem += "between ";
        problem += formatReal(range.low);
        problem += " and ";
    }
    problem += formatReal(range.high);
    if (!range.unit.empty()) {
        problem += ' ';
        problem += range.unit;
    }
    problem += ", got ";
    problem += formatReal(value);
    problem += context;
    problem += " (valid ranges: docs/scenario-format.md)";
    fail(node, key, problem);
}

Vec3 TomlReader::vec3(const toml::node& node, const std::string& key) const
{
    const toml::array* array = node.as_array();
    if (array == nullptr || array->size() != 3) {
        fail(node, key, "expected an array of 3 numbers [x, y, z], got " + describeNode(node));
    }
    Vec3 value{0.0};
    for (int i = 0; i < 3; ++i) {
        value[i] =
            real(*array->get(static_cast<std::size_t>(i)), key + "[" + std::to_string(i) + "]");
    }
    return value;
}

Vec3 TomlReader::positiveVec3(const toml::node& node, const std::string& key,
                              const std::string& context) const
{
    const Vec3 value = vec3(node, key);
    if (!(value.x > 0.0 && value.y > 0.0 && value.z > 0.0)) {
        fail(node, key, "every component must be > 0, got " + formatVec3(value) + context);
    }
    return value;
}

long long TomlReader::integer(const toml::node& node, const std::string& key) const
{
    if (const auto* value = node.as_integer()) {
        return value->get();
    }
    fail(node, key, "expected an integer, got " + describeNode(node));
}

bool TomlReader::boolean(const toml::node& node, const std::string& key) const
{
    if (const auto* value = node.as_boolean()) {
        return value->get();
    }
    fail(node, key, "expected true or false, got " + describeNode(node));
}

std::string TomlReader::string(const toml::node& node, const std::string& key) const
{
    if (const auto* value = node.as_string()) {
        return value->get();
    }
    fail(node, key, "expected a string, got " + describeNode(node));
}

std::size_t TomlReader::choice(const toml::node& node, const std::string& key,
                               std::span<const std::string_view> allowed) const
{
    const std::string value = string(node, key);
    const auto found = std::find(allowed.begin(), allowed.end(), value);
    if (found == allowed.end()) {
        std::string list;
        for (const std::string_view option : allowed) {
            list += list.empty() ? "\"" : ", \"";
            list += option;
            list += '"';
        }
        fail(node, key, "must be one of " + list + ", got \"" + value + "\"");
    }
    return static_cast<std::size_t>(found - allowed.begin());
}

Quat TomlReader::orientation(const toml::node& node, const std::string& key) const
{
    if (const toml::array* array = node.as_array(); array != nullptr && array->size() == 4) {
        std::array<Real, 4> wxyz{};
        for (std::size_t i = 0; i < 4; ++i) {
            wxyz[i] = real(*array->get(i), key + "[" + std::to_string(i) + "]");
        }
        const Quat q(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
        const Real length = glm::length(q);
        if (!(std::abs(length - 1.0) <= kUnitQuaternionTolerance)) {
            fail(node, key,
                 "not a unit quaternion: |q| = " + formatReal(length) +
                     " (w, x, y, z must have length 1 within 1e-6; or give { axis = [x, y, z], "
                     "degrees = a })");
        }
        // the same function runThrow applies, so a replayed throw starts where the throw did
        return normalizedOrientation(q);
    }
    if (const toml::table* angle = node.as_table()) {
        checkKeys(*angle, key, kAxisAngleKeys);
        const toml::node* axisNode = angle->get("axis");
        const toml::node* degreesNode = angle->get("degrees");
        if (axisNode == nullptr || degreesNode == nullptr) {
            fail(node, key, "an axis-angle orientation needs both axis and degrees");
        }
        const Vec3 axis = vec3(*axisNode, key + ".axis");
        const Real axisLength = vectorLength(axis);
        if (!(axisLength > 0.0) || !std::isfinite(axisLength)) {
            fail(*axisNode, key + ".axis", "must be a nonzero vector, got " + formatVec3(axis));
        }
        const Real degrees = real(*degreesNode, key + ".degrees");
        return axisAngle(axis / axisLength, degrees * std::numbers::pi / 180.0);
    }
    fail(node, key,
         "expected a unit quaternion [w, x, y, z] or { axis = [x, y, z], degrees = a }, got " +
             describeNode(node));
}

} // namespace tumble::scenario::detail
