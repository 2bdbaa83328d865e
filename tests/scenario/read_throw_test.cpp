// The [throw] table: defaults, every key read, and each bad value reported with file, line and
// key.
#include "tumble/scenario/scenario.hpp"

#include "scenario/expect_scenario_error.hpp"

#include <gtest/gtest.h>

#include <string>

namespace tumble::scenario {
namespace {

using test_support::failsWith;

/// A die scene with `throwTable` after its [throw] line (line 6 is the first key).
std::string diceScene(const std::string& throwTable)
{
    return "[ground]\n"                                  // 1
           "[[body]]\n"                                  // 2
           "name = \"die\"\n"                            // 3
           "size = [0.02, 0.02, 0.02]\n"                 // 4
           "[throw]\n" +                                 // 5
           throwTable;
}

TEST(ReadThrow, AbsentTableMeansNoThrowSpec)
{
    EXPECT_FALSE(parseScenario("[ground]\n[[body]]\nposition = [0, 1, 0]\n", "scene.toml").throwSpec.has_value());
}

TEST(ReadThrow, EmptyTableTakesTheDefaults)
{
    const Scenario scenario = parseScenario(diceScene(""), "scene.toml");
    ASSERT_TRUE(scenario.throwSpec.has_value());
    EXPECT_EQ(scenario.throwSpec->height.min, 0.5);
    EXPECT_EQ(scenario.throwSpec->height.max, 1.0);
    EXPECT_EQ(scenario.throwSpec->verticalSpeed.min, -1.0);
    EXPECT_EQ(scenario.throwSpec->angularSpeed.max, 20.0);
    EXPECT_EQ(scenario.throwSpec->maxTime, 20.0);
    EXPECT_EQ(scenario.throwSpec->orientation, ThrowOrientation::Random);
}

TEST(ReadThrow, ReadsEveryKey)
{
    const Scenario scenario = parseScenario(
        diceScene("height = [0.2, 0.3]\nspeed = 1\nvertical_speed = [-2, 1]\n"
                  "angular_speed = [0, 3]\norientation = \"body\"\nmax_time = 4\n"),
        "scene.toml");
    const ThrowSpec& spec = *scenario.throwSpec;
    EXPECT_EQ(spec.height.min, 0.2);
    EXPECT_EQ(spec.height.max, 0.3);
    EXPECT_EQ(spec.speed.min, 1.0);
    EXPECT_EQ(spec.speed.max, 1.0);
    EXPECT_EQ(spec.verticalSpeed.max, 1.0);
    EXPECT_EQ(spec.angularSpeed.min, 0.0);
    EXPECT_EQ(spec.orientation, ThrowOrientation::Body);
    EXPECT_EQ(spec.maxTime, 4.0);
}

TEST(ReadThrow, RangeWithMinAboveMax)
{
    EXPECT_TRUE(failsWith(diceScene("height = [1.0, 0.5]\n"), "scene.toml:6: throw.height: ",
                          "min must be <= max, got [1, 0.5]"));
}

TEST(ReadThrow, NegativeHeight)
{
    EXPECT_TRUE(failsWith(diceScene("height = [-0.5, 1.0]\n"), "scene.toml:6: throw.height: ",
                          "must be >= 0"));
}

TEST(ReadThrow, HeightBelowHalfTheDiagonal)
{
    EXPECT_TRUE(failsWith(diceScene("height = [0.01, 1.0]\n"), "scene.toml:6: throw.height: ",
                          "half the die's diagonal"));
}

TEST(ReadThrow, RangeOfTheWrongShape)
{
    EXPECT_TRUE(failsWith(diceScene("speed = [1, 2, 3]\n"), "scene.toml:6: throw.speed: ",
                          "expected a range [min, max]"));
    EXPECT_TRUE(failsWith(diceScene("speed = [1, \"x\"]\n"), "scene.toml:6: throw.speed[1]: ",
                          "expected a number"));
}

TEST(ReadThrow, NegativeSpeedsAndSpins)
{
    EXPECT_TRUE(failsWith(diceScene("speed = [-1, 2]\n"), "scene.toml:6: throw.speed: ",
                          "must be >= 0"));
    EXPECT_TRUE(failsWith(diceScene("angular_speed = [-1, 2]\n"),
                          "scene.toml:6: throw.angular_speed: ", "must be >= 0"));
}

TEST(ReadThrow, SpinTooFastForTheStep)
{
    EXPECT_TRUE(failsWith(diceScene("angular_speed = [5, 200]\n"),
                          "scene.toml:6: throw.angular_speed: ",
                          "the largest angle turned in one step"));
}

TEST(ReadThrow, NonPositiveMaxTime)
{
    EXPECT_TRUE(failsWith(diceScene("max_time = 0\n"), "scene.toml:6: throw.max_time: ",
                          "must be > 0, got 0"));
    EXPECT_TRUE(failsWith(diceScene("max_time = -3\n"), "scene.toml:6: throw.max_time: ",
                          "must be > 0"));
}

TEST(ReadThrow, UnknownKeySuggestsTheClosestOne)
{
    EXPECT_TRUE(failsWith(diceScene("heigth = [0.5, 1]\n"), "scene.toml:6: throw.heigth: ",
                          "did you mean 'height'?"));
}

TEST(ReadThrow, UnknownOrientation)
{
    EXPECT_TRUE(failsWith(diceScene("orientation = \"spinning\"\n"),
                          "scene.toml:6: throw.orientation: ",
                          "must be one of \"random\", \"body\""));
}

TEST(ReadThrow, SeveralDiceWithoutARegionOrCluster)
{
    // released each on its own above the origin, two dice would start inside each other
    EXPECT_TRUE(failsWith("[ground]\n[[body]]\nposition = [-5, 2, 0]\n[[body]]\n"
                          "position = [5, 2, 0]\n[throw]\n",
                          "scene.toml:6: throw: ", "several dice need a region"));
}

TEST(ReadThrow, NoGround)
{
    EXPECT_TRUE(failsWith("[[body]]\n[throw]\n", "scene.toml:2: throw: ", "needs a [ground]"));
}

TEST(ReadThrow, NotATable)
{
    EXPECT_TRUE(failsWith("throw = 3\n[ground]\n[[body]]\n", "scene.toml:1: throw: ",
                          "expected a table"));
}

TEST(ReadThrow, OverrideOfAThrowKeyIsCheckedLikeTheFile)
{
    const std::vector<std::string> overrides{"throw.max_time=-1"};
    EXPECT_TRUE(failsWith(diceScene(""), "--set: throw.max_time: ", "must be > 0", overrides));
    const std::vector<std::string> good{"throw.speed=[0, 0.1]"};
    EXPECT_EQ(parseScenario(diceScene(""), "scene.toml", good).throwSpec->speed.max, 0.1);
}

} // namespace
} // namespace tumble::scenario
