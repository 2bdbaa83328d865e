// --set overrides: "KEY=VALUE" strings applied to a parsed scenario table before it is validated.
#include "overrides.hpp"

#include "messages.hpp"
#include "schema.hpp"
#include "toml_reader.hpp"

#include "tumble/scenario/scenario.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <optional>
#include <string_view>

namespace tumble::scenario::detail {

namespace {

constexpr std::string_view kTargetsHint =
    "world.<key>, ground.height, throw.<key>, <body name>.<key>, impulse[<index>].<key> or "
    "spawn[<index>].<key>";

[[noreturn]] void failOverride(const std::string& key, const std::string& problem)
{
    throw ScenarioError(SourceLocation{"--set", 0}, key, problem);
}

std::string_view trim(std::string_view text)
{
    const auto isSpace = [](char c) {
        return std::isspace(static_cast<unsigned char>(c)) != 0;
    };
    while (!text.empty() && isSpace(text.front())) {
        text.remove_prefix(1);
    }
    while (!text.empty() && isSpace(text.back())) {
        text.remove_suffix(1);
    }
    return text;
}

/// A word that may stand for a string without quotes: `handout`, `average`, `rb2`.
bool isBareWord(std::string_view text)
{
    return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' ||
               c == '.' || c == '+';
    });
}

/// The table an override writes into, its key in file terms ("body[0]") and its known keys.
struct Target {
    toml::table* table = nullptr;
    std::string fileKey;
    std::span<const std::string_view> known;
};

toml::table& tableOrCreate(toml::table& root, std::string_view name, const std::string& key)
{
    if (toml::node* node = root.get(name)) {
        if (toml::table* existing = node->as_table()) {
            return *existing;
        }
        failOverride(key, "'" + std::string(name) + "' in the scenario is not a table");
    }
    return *root.insert_or_assign(name, toml::table{}).first->second.as_table();
}

/// The array of tables `name` ([[body]], [[impulse]]), or null when the scenario has none.
toml::array* arrayOfTables(toml::table& root, std::string_view name, const std::string& key)
{
    toml::node* node = root.get(name);
    if (node == nullptr) {
        return nullptr;
    }
    toml::array* array = node->as_array();
    if (array == nullptr || !array->is_array_of_tables()) {
        failOverride(key, "'" + std::string(name) + "' in the scenario is not an array of tables");
    }
    return array;
}

std::optional<std::size_t> parseIndex(std::string_view section, std::string_view name)
{
    if (!section.starts_with(name) || !section.ends_with(']') || section.size() < name.size() + 3 ||
        section[name.size()] != '[') {
        return std::nullopt;
    }
    const std::string_view digits =
        section.substr(name.size() + 1, section.size() - name.size() - 2);
    std::size_t index = 0;
    const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), index);
    if (result.ec != std::errc{} || result.ptr != digits.data() + digits.size()) {
        return std::nullopt;
    }
    return index;
}

/// Entry `index` of the array of tables `name` ([[impulse]], [[spawn]]).
Target indexedTarget(toml::table& root, std::string_view name, std::size_t index,
                     std::span<const std::string_view> known, const std::string& key)
{
    toml::array* entries = arrayOfTables(root, name, key);
    const std::size_t count = entries == nullptr ? 0 : entries->size();
    const std::string label = std::string(name) + "[" + std::to_string(index) + "]";
    if (index >= count) {
        failOverride(key, "no " + label + ": the scenario has " + std::to_string(count) + " [[" +
                              std::string(name) + "]] entries");
    }
    return Target{entries->get(index)->as_table(), label, known};
}

Target bodyTarget(toml::table& root, std::string_view section, const std::string& key)
{
    toml::array* bodies = arrayOfTables(root, "body", key);
    const std::size_t count = bodies == nullptr ? 0 : bodies->size();
    std::string names;
    for (std::size_t i = 0; i < count; ++i) {
        toml::table* body = bodies->get(i)->as_table();
        const std::optional<std::string> name = (*body)["name"].value<std::string>();
        const std::string effective = name.value_or("body" + std::to_string(i + 1));
        if (effective == section || (section == "body" && count == 1)) {
            return Target{body, "body[" + std::to_string(i) + "]", kBodyKeys};
        }
        names += names.empty() ? "" : ", ";
        names += effective;
    }
    failOverride(key, "no body named '" + std::string(section) +
                          "' (bodies: " + (names.empty() ? "none" : names) + "; KEY is " +
                          std::string(kTargetsHint) + ")");
}

Target findTarget(toml::table& root, std::string_view section, const std::string& key)
{
    if (section == "world") {
        return Target{&tableOrCreate(root, "world", key), "world", kWorldKeys};
    }
    if (section == "ground") {
        return Target{&tableOrCreate(root, "ground", key), "ground", kGroundKeys};
    }
    if (section == "throw") {
        return Target{&tableOrCreate(root, "throw", key), "throw", kThrowKeys};
    }
    if (const std::optional<std::size_t> index = parseIndex(section, "impulse")) {
        return indexedTarget(root, "impulse", *index, kImpulseKeys, key);
    }
    if (const std::optional<std::size_t> index = parseIndex(section, "spawn")) {
        return indexedTarget(root, "spawn", *index, kSpawnKeys, key);
    }
    return bodyTarget(root, section, key);
}

/// Parses VALUE as the TOML value of `v = VALUE`; a bare word that is not TOML becomes a string.
/// The nodes carry a source path that names the override (see overrideSourcePath).
toml::table parseValue(std::string_view value, const std::string& key, const std::string& fileKey)
{
    const std::string path = overrideSourcePath(key, fileKey);
    toml::table parsed;
    try {
        parsed = toml::parse(std::string_view("v = " + std::string(value)), std::string_view(path));
    } catch (const toml::parse_error& error) {
        if (!isBareWord(value)) {
            failOverride(key, "cannot read '" + std::string(value) +
                                  "' as a TOML value: " + std::string(error.description()));
        }
        parsed = toml::parse(std::string_view("v = \"" + std::string(value) + "\""),
                             std::string_view(path));
    }
    if (parsed.size() != 1 || !parsed.contains("v")) {
        failOverride(key, "'" + std::string(value) + "' is not a single TOML value");
    }
    return parsed;
}

/// Keys that cannot stand together with `key` in a body or impulse: setting one removes the others.
std::span<const std::string_view> displacedBy(std::string_view key, bool isImpulse)
{
    static constexpr std::array<std::string_view, 1> kScaleKey{"scale"};
    static constexpr std::array<std::string_view, 1> kSizeKey{"size"};
    static constexpr std::array<std::string_view, 2> kDirectKeys{"impulse", "offset"};
    static constexpr std::array<std::string_view, 2> kTargetKeys{"velocity", "angular_velocity"};
    if (!isImpulse) {
        if (key == "size") {
            return kScaleKey;
        }
        if (key == "scale") {
            return kSizeKey;
        }
        return {};
    }
    if (key == "impulse" || key == "offset") {
        return kTargetKeys;
    }
    if (key == "velocity" || key == "angular_velocity") {
        return kDirectKeys;
    }
    return {};
}

void applyOverride(toml::table& root, std::string_view text)
{
    const std::size_t equals = text.find('=');
    const std::string key(trim(text.substr(0, equals)));
    if (equals == std::string_view::npos || key.empty()) {
        failOverride(std::string(text),
                     "expected KEY=VALUE with KEY one of " + std::string(kTargetsHint));
    }
    const std::string_view value = trim(text.substr(equals + 1));
    if (value.empty()) {
        failOverride(key, "missing value after '='");
    }
    const std::size_t dot = key.rfind('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == key.size()) {
        failOverride(key, "expected " + std::string(kTargetsHint));
    }
    const std::string_view leaf = std::string_view(key).substr(dot + 1);
    const Target target = findTarget(root, std::string_view(key).substr(0, dot), key);
    if (std::find(target.known.begin(), target.known.end(), leaf) == target.known.end()) {
        failOverride(key, unknownKeyProblem(leaf, target.known));
    }
    const bool isImpulse = target.fileKey.starts_with("impulse[");
    toml::table parsed = parseValue(value, key, target.fileKey + "." + std::string(leaf));
    // size/scale, and impulse/offset against velocity/angular_velocity, are alternatives: the
    // override replaces whichever the file gave.
    for (const std::string_view other : displacedBy(leaf, isImpulse)) {
        target.table->erase(other);
    }
    target.table->insert_or_assign(leaf, std::move(*parsed.get("v")));
}

} // namespace

void applyOverrides(toml::table& root, std::span<const std::string> overrides)
{
    for (const std::string& text : overrides) {
        applyOverride(root, text);
    }
}

} // namespace tumble::scenario::detail
