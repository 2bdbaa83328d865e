#include "viewer/scenario_catalog.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

namespace tumble::viewer {
namespace {

TEST(ScenarioCatalog, ListsHandoutScenariosFirstThenTheOthers)
{
    const std::vector<ScenarioEntry> entries = listScenarios(TUMBLE_SCENARIO_DIR);
    ASSERT_GE(entries.size(), 9u);
    // the number keys 1..9 reach every handout scenario
    const auto firstOther = std::find_if(entries.begin(), entries.end(), [](const ScenarioEntry& e) {
        return !e.name.starts_with("part");
    });
    EXPECT_TRUE(std::all_of(firstOther, entries.end(),
                            [](const ScenarioEntry& e) { return !e.name.starts_with("part"); }));
    EXPECT_LE(firstOther - entries.begin(), 9);
    EXPECT_TRUE(std::is_sorted(entries.begin(), firstOther,
                               [](const ScenarioEntry& a, const ScenarioEntry& b) {
                                   return a.name < b.name;
                               }));
    EXPECT_EQ(entries.front().name, "part2_task2_impulses");
    for (const ScenarioEntry& entry : entries) {
        EXPECT_EQ(entry.path.extension(), ".toml");
    }
}

TEST(ScenarioCatalog, MissingFolderListsNothing)
{
    EXPECT_TRUE(listScenarios("/no/such/folder").empty());
}

/// Runs the test body with the working directory set to a fresh temporary folder.
class InTemporaryFolder : public ::testing::Test {
protected:
    void SetUp() override
    {
        m_previous = std::filesystem::current_path();
        // one folder per process and test: ctest runs tests side by side
        m_folder = std::filesystem::temp_directory_path() /
                   ("tumble_viewer_" + std::to_string(getpid()) + "_" +
                    ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(m_folder);
        std::filesystem::create_directories(m_folder);
        std::filesystem::current_path(m_folder);
    }
    void TearDown() override
    {
        std::filesystem::current_path(m_previous);
        std::filesystem::remove_all(m_folder);
    }

private:
    std::filesystem::path m_previous;
    std::filesystem::path m_folder;
};

using ScenarioDirectory = InTemporaryFolder;

TEST_F(ScenarioDirectory, FallsBackToTheBuiltInFolder)
{
    EXPECT_EQ(findScenarioDirectory(TUMBLE_SCENARIO_DIR), TUMBLE_SCENARIO_DIR);
}

TEST_F(ScenarioDirectory, PrefersScenariosUnderTheWorkingDirectory)
{
    std::filesystem::create_directories("scenarios");
    std::ofstream(std::filesystem::path("scenarios") / kDefaultScenarioFile) << "[[body]]\n";
    EXPECT_EQ(findScenarioDirectory(TUMBLE_SCENARIO_DIR), "scenarios");
}

} // namespace
} // namespace tumble::viewer
