// Determinism: the same scenario gives bit-identical states however often it is run, whatever
// else the process did in between, and the state hash tells any difference. Across -O0 and -O2
// builds it is checked by tools/ci-determinism.sh (`tumble run --hash` on every scenario).
#include "tumble/scenario/runner.hpp"
#include "tumble/scenario/scenario.hpp"
#include "tumble/state_hash.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace tumble::robustness {
namespace {

/// Overrides for a scenario too long to run whole here, as in the runner test (runner_test.cpp):
/// pile_100.toml (benchmark S5) steps for about a minute over its 10 s, so its first 0.5 s run,
/// in which the lower layers land on each other.
std::vector<std::string> shortened(const std::filesystem::path& file)
{
    if (file.filename() == "pile_100.toml") {
        return {"world.duration=0.5"};
    }
    return {};
}

std::uint64_t runToEnd(const std::filesystem::path& file)
{
    scenario::Runner runner(scenario::loadScenario(file, shortened(file)));
    const long long steps = std::llround(runner.scenario().duration / runner.scenario().dt);
    for (long long i = 0; i < steps; ++i) {
        runner.step();
    }
    return stateHash(runner.world(), runner.bodies());
}

std::vector<std::filesystem::path> scenarioFiles()
{
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(TUMBLE_SCENARIO_DIR)) {
        if (entry.path().extension() == ".toml") {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

TEST(Determinism, EveryScenarioHashesTheSameOnEveryRun)
{
    std::map<std::string, std::uint64_t> first;
    for (const auto& file : scenarioFiles()) {
        first[file.filename().string()] = runToEnd(file);
    }
    // Again in the opposite order, so no state left over from one run can leak into the next.
    const auto files = scenarioFiles();
    for (auto it = files.rbegin(); it != files.rend(); ++it) {
        EXPECT_EQ(runToEnd(*it), first[it->filename().string()]) << *it;
    }
    EXPECT_GE(first.size(), 10u);
}

TEST(Determinism, InterleavedWorldsMatchAWorldSteppedAlone)
{
    const auto file = std::filesystem::path(TUMBLE_SCENARIO_DIR) / "part3_task4_friction.toml";
    const std::uint64_t alone = runToEnd(file);
    scenario::Runner a(scenario::loadScenario(file));
    scenario::Runner b(scenario::loadScenario(file));
    const long long steps = std::llround(a.scenario().duration / a.scenario().dt);
    for (long long i = 0; i < steps; ++i) {
        a.step();
        b.step();
    }
    EXPECT_EQ(stateHash(a.world(), a.bodies()), alone);
    EXPECT_EQ(stateHash(b.world(), b.bodies()), alone);
}

TEST(Determinism, TheHashSeesTheSmallestChange)
{
    World world;
    const BodyId id = world.createBody(BodyDef{});
    const std::uint64_t before = stateHash(world);
    world.setLinearVelocity(id, Vec3(0.0, std::nextafter(0.0, 1.0), 0.0));
    EXPECT_NE(stateHash(world), before);
    world.setLinearVelocity(id, Vec3(0.0));
    EXPECT_EQ(stateHash(world), before);
    // FNV-1a 64 of nothing is its offset basis.
    EXPECT_EQ(stateHash(world, {}), kFnvOffsetBasis);
}

} // namespace
} // namespace tumble::robustness
