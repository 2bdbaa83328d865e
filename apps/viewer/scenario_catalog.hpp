// The scenario files the viewer offers: the picker's list, the number keys' order, and where
// `tumble view` looks for the default scenario.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace tumble::viewer {

/// The scenario `tumble view` opens when given no file (handout part 3, task 4).
inline constexpr const char* kDefaultScenarioFile = "part3_task4_friction.toml";

struct ScenarioEntry {
    /// File name without the extension.
    std::string name;
    std::filesystem::path path;
};

/// The *.toml files of `directory`: the handout scenarios (names starting with "part") first,
/// then the others, each group sorted by name. Empty when the directory cannot be read.
std::vector<ScenarioEntry> listScenarios(const std::filesystem::path& directory);

/// `scenarios/` under the working directory when it holds the default scenario, else
/// `builtIn` (the source tree's scenarios/, compiled in).
std::filesystem::path findScenarioDirectory(const std::filesystem::path& builtIn);

} // namespace tumble::viewer
