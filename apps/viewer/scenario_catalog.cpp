#include "viewer/scenario_catalog.hpp"

#include <algorithm>
#include <system_error>

namespace tumble::viewer {
namespace {

bool isHandout(const ScenarioEntry& entry) { return entry.name.starts_with("part"); }

} // namespace

std::vector<ScenarioEntry> listScenarios(const std::filesystem::path& directory)
{
    std::vector<ScenarioEntry> entries;
    std::error_code error;
    for (const auto& item : std::filesystem::directory_iterator(directory, error)) {
        if (item.path().extension() == ".toml") {
            entries.push_back({item.path().stem().string(), item.path()});
        }
    }
    std::sort(entries.begin(), entries.end(), [](const ScenarioEntry& a, const ScenarioEntry& b) {
        if (isHandout(a) != isHandout(b)) {
            return isHandout(a);
        }
        return a.name < b.name;
    });
    return entries;
}

std::filesystem::path findScenarioDirectory(const std::filesystem::path& builtIn)
{
    std::error_code error;
    const std::filesystem::path local = "scenarios";
    if (std::filesystem::exists(local / kDefaultScenarioFile, error)) {
        return local;
    }
    return builtIn;
}

} // namespace tumble::viewer
