// Running throws: a fair cube lands on each face a sixth of the time, and a throw written as a
// scenario file runs through the Runner (what `tumble run` uses) to the same face at the same
// rest time.
#include "tumble/scenario/throw.hpp"

#include "tumble/scenario/dice_statistics.hpp"
#include "tumble/scenario/runner.hpp"
#include "tumble/scenario/scenario.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace tumble::scenario {
namespace {

const std::filesystem::path kDiceCube = std::filesystem::path(TUMBLE_SCENARIO_DIR) / "dice_cube.toml";

/// The first RestEvent of a Runner over the scenario's duration, as a ThrowOutcome.
ThrowOutcome runThroughRunner(const Scenario& scenario)
{
    Runner runner(scenario);
    const long long steps = stepCountFor(scenario.duration, scenario.dt);
    for (long long i = 0; i < steps; ++i) {
        const StepReport report = runner.step();
        if (!report.restEvents.empty()) {
            return ThrowOutcome{.settled = true,
                                .faceDown = report.restEvents.front().faceDown,
                                .restTime = report.restEvents.front().time};
        }
    }
    return ThrowOutcome{};
}

TEST(ThrowRun, ACubeLandsOnEveryFaceWithProbabilityOneSixth)
{
    // 3000 throws: each face count within the 99.9% Wilson interval, and the chi-square test of
    // uniformity not rejected at 0.001. A biased engine (a face favoured by 2 percentage points
    // or more) fails the chi-square test with high probability at this size.
    const Scenario dice = loadScenario(kDiceCube);
    constexpr std::int64_t kThrows = 3000;
    std::array<std::int64_t, 6> counts{};
    std::int64_t settled = 0;
    for (std::int64_t i = 0; i < kThrows; ++i) {
        const ThrowOutcome outcome =
            runThrow(dice, drawThrow(dice, 2024, static_cast<std::uint64_t>(i)));
        if (outcome.settled) {
            ++counts[static_cast<std::size_t>(outcome.faceDown)];
            ++settled;
        }
    }
    EXPECT_GE(settled, kThrows - 3);
    for (std::size_t face = 0; face < counts.size(); ++face) {
        const ProbabilityInterval interval = wilsonInterval(counts[face], settled, 0.999);
        EXPECT_LE(interval.low, 1.0 / 6.0) << faceName(static_cast<CuboidFace>(face));
        EXPECT_GE(interval.high, 1.0 / 6.0) << faceName(static_cast<CuboidFace>(face));
    }
    EXPECT_GT(chiSquarePValue(chiSquareUniformStatistic(counts), 5), 0.001);
}

TEST(ThrowRun, ReplayedFileGivesTheSameFaceAndRestTimeThroughTheRunner)
{
    const Scenario dice = loadScenario(kDiceCube);
    int settled = 0;
    for (std::uint64_t index : {0U, 1U, 2U, 17U, 123U, 4567U}) {
        SCOPED_TRACE(index);
        const ThrowState state = drawThrow(dice, 42, index);
        const ThrowOutcome thrown = runThrow(dice, state);
        const std::string text = throwScenarioToml(dice, state, "replay test");
        const Scenario replay = parseScenario(text, "replay.toml");
        EXPECT_FALSE(replay.throwSpec.has_value());
        EXPECT_EQ(replay.duration, dice.throwSpec->maxTime);
        const ThrowOutcome replayed = runThroughRunner(replay);
        ASSERT_EQ(replayed.settled, thrown.settled);
        EXPECT_EQ(replayed.faceDown, thrown.faceDown);
        EXPECT_EQ(replayed.restTime, thrown.restTime);
        settled += thrown.settled ? 1 : 0;
        // and the data path, without text, agrees too
        const ThrowOutcome direct = runThroughRunner(throwScenario(dice, state));
        EXPECT_EQ(direct.restTime, thrown.restTime);
    }
    EXPECT_GE(settled, 5);
}

TEST(ThrowRun, ReplayFileLoadsTheDrawnStateBitForBit)
{
    const Scenario dice =
        loadScenario(kDiceCube, std::vector<std::string>{"ground.height=0.1", "die.mass=0.0071",
                                                         "die.static_friction=0.7"});
    const ThrowState state = drawThrow(dice, 3, 9);
    const Scenario replay = parseScenario(throwScenarioToml(dice, state, "x"), "replay.toml");
    const BodyDef& def = replay.bodies.front().def;
    EXPECT_EQ(def.position, state.position);
    EXPECT_EQ(def.linearVelocity, state.velocity);
    EXPECT_EQ(def.angularVelocity, state.angularVelocity);
    EXPECT_EQ(def.orientation, normalizedOrientation(state.orientation));
    EXPECT_EQ(def.mass, dice.bodies.front().def.mass);
    EXPECT_EQ(def.material.staticFriction, dice.bodies.front().def.material.staticFriction);
    EXPECT_EQ(replay.dt, dice.dt);
    EXPECT_EQ(replay.ground->height, dice.ground->height);
    EXPECT_EQ(replay.settings.gravity, dice.settings.gravity);
}

TEST(ThrowRun, AThrowNotAtRestByMaxTimeIsUnsettled)
{
    const Scenario dice = loadScenario(kDiceCube, std::vector<std::string>{"throw.max_time=0.1"});
    const ThrowOutcome outcome = runThrow(dice, drawThrow(dice, 1, 0));
    EXPECT_FALSE(outcome.settled);
}

} // namespace
} // namespace tumble::scenario
