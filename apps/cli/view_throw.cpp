// `tumble view FILE --throw I`: the replay of throw I, written where the viewer can open it.
#include "view_throw.hpp"

#include "tumble/scenario/scenario.hpp"
#include "tumble/scenario/throw.hpp"
#include "tumble/scenario/throw_dice.hpp"

#include <unistd.h>

#include <fstream>
#include <string>

namespace tumble::cli {

ThrowViewFile::ThrowViewFile(const ViewOptions& given) : m_options(given)
{
    if (given.throwIndex < 0) {
        return;
    }
    const scenario::Scenario loaded = scenario::loadScenario(given.file, given.overrides);
    if (!loaded.throwSpec) {
        throw scenario::ScenarioError(scenario::SourceLocation{given.file, 0}, "--throw",
                                      "the scenario has no [throw] table to draw the throw from");
    }
    const auto index = static_cast<std::uint64_t>(given.throwIndex);
    const std::string comment = "Throw " + std::to_string(index) + " of " + given.file +
                                " with seed " + std::to_string(given.seed) + " (tumble view).";
    // the single-die model and the dice model draw the one die alike (docs/dice.md)
    const std::string text = scenario::diceScenarioToml(
        loaded, scenario::drawDice(loaded, given.seed, index), comment);
    m_written = std::filesystem::temp_directory_path() /
                ("tumble_view_throw_" + std::to_string(getpid()) + ".toml");
    std::ofstream(m_written) << text;
    m_options.file = m_written.string();
    m_options.overrides.clear();
}

ThrowViewFile::~ThrowViewFile()
{
    if (!m_written.empty()) {
        std::error_code ignored;
        std::filesystem::remove(m_written, ignored);
    }
}

} // namespace tumble::cli
