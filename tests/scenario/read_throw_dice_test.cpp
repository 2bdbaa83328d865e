// The [throw] keys of several dice: release, cluster_radius, region and heading, each bad value
// reported with file, line and key.
#include "tumble/scenario/scenario.hpp"

#include "scenario/expect_scenario_error.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <string>

namespace tumble::scenario {
namespace {

using test_support::failsWith;

/// Two dice and a floor, with `throwTable` after its [throw] line (line 12 is the first key).
std::string twoDice(const std::string& throwTable)
{
    return "[[body]]\n"                                  // 1
           "motion = \"static\"\n"                       // 2
           "size = [1, 0.02, 1]\n"                       // 3
           "position = [0, -0.01, 0]\n"                  // 4
           "[[body]]\n"                                  // 5
           "size = [0.02, 0.02, 0.02]\n"                 // 6
           "position = [-0.1, 0.1, 0]\n"                 // 7
           "[[body]]\n"                                  // 8
           "size = [0.02, 0.02, 0.02]\n"                 // 9
           "position = [0.1, 0.1, 0]\n"                  // 10
           "[throw]\n" +                                 // 11
           throwTable;
}

const std::string kRegion = "region = { min = [-0.1, 0.1, -0.1], max = [0.1, 0.2, 0.1] }\n";

TEST(ReadThrowDice, RegionAndReleaseAreRead)
{
    const Scenario scenario =
        parseScenario(twoDice(kRegion + "release = \"cluster\"\ncluster_radius = 0.05\n"
                                        "heading = [-90, 90]\n"),
                      "scene.toml");
    ASSERT_TRUE(scenario.throwSpec.has_value());
    const ThrowSpec& spec = *scenario.throwSpec;
    ASSERT_TRUE(spec.region.has_value());
    EXPECT_EQ(spec.region->min, Vec3(-0.1, 0.1, -0.1));
    EXPECT_EQ(spec.region->max, Vec3(0.1, 0.2, 0.1));
    EXPECT_EQ(spec.release, ThrowRelease::Cluster);
    EXPECT_EQ(spec.clusterRadius, 0.05);
    EXPECT_DOUBLE_EQ(spec.heading.min, -0.5 * std::numbers::pi);
    EXPECT_DOUBLE_EQ(spec.heading.max, 0.5 * std::numbers::pi);
}

TEST(ReadThrowDice, DefaultsKeepTheSingleDieModel)
{
    const Scenario scenario = parseScenario("[ground]\n[[body]]\nsize = [0.02, 0.02, 0.02]\n"
                                            "[throw]\n",
                                            "scene.toml");
    const ThrowSpec& spec = *scenario.throwSpec;
    EXPECT_EQ(spec.release, ThrowRelease::Each);
    EXPECT_FALSE(spec.region.has_value());
    EXPECT_EQ(spec.clusterRadius, 0.03);
    EXPECT_EQ(spec.heading.min, 0.0);
    EXPECT_EQ(spec.heading.max, 2.0 * std::numbers::pi);
}

TEST(ReadThrowDice, SeveralDiceNeedARegionOrACluster)
{
    EXPECT_TRUE(failsWith("[ground]\n" + twoDice(""), "scene.toml:12: throw: ",
                          "several dice need a region"));
    EXPECT_NO_THROW((void)parseScenario("[ground]\n" + twoDice("release = \"cluster\"\n"),
                                        "scene.toml"));
}

TEST(ReadThrowDice, WithoutARegionAGroundIsNeeded)
{
    EXPECT_TRUE(failsWith(twoDice("release = \"cluster\"\n"), "scene.toml:11: throw: ",
                          "needs a [ground]"));
}

TEST(ReadThrowDice, BadRegions)
{
    EXPECT_TRUE(failsWith(twoDice("region = { min = [0, 0.3, 0], max = [0.1, 0.2, 0.1] }\n"),
                          "scene.toml:12: throw.region: ", "min must be <= max"));
    EXPECT_TRUE(failsWith(twoDice("region = { min = [0, 0.1, 0] }\n"),
                          "scene.toml:12: throw.region.max: ", "missing"));
    EXPECT_TRUE(failsWith(twoDice("region = { min = [0, 0.1, 0], max = [1, 1, 1], mid = 2 }\n"),
                          "scene.toml:12: throw.region.mid: ", "unknown key"));
    EXPECT_TRUE(failsWith(twoDice("region = [0, 1]\n"), "scene.toml:12: throw.region: ",
                          "expected a table"));
    EXPECT_TRUE(failsWith(twoDice(kRegion + "height = 1\n"), "scene.toml:13: throw.height: ",
                          "either height or region"));
}

TEST(ReadThrowDice, BadReleaseAndCluster)
{
    EXPECT_TRUE(failsWith(twoDice(kRegion + "release = \"both\"\n"),
                          "scene.toml:13: throw.release: ", "must be one of \"each\", \"cluster\""));
    EXPECT_TRUE(failsWith(twoDice(kRegion + "cluster_radius = 0.1\n"),
                          "scene.toml:13: throw.cluster_radius: ", "only with release"));
    EXPECT_TRUE(failsWith(twoDice(kRegion + "release = \"cluster\"\ncluster_radius = -1\n"),
                          "scene.toml:14: throw.cluster_radius: ", "must be > 0"));
    EXPECT_TRUE(failsWith(twoDice(kRegion + "heading = [0, 400]\n"),
                          "scene.toml:13: throw.heading: ", "within [-360, 360]"));
}

TEST(ReadThrowDice, AThrowNeedsADie)
{
    EXPECT_TRUE(failsWith("[ground]\n[[body]]\nmotion = \"static\"\n[throw]\n",
                          "scene.toml:4: throw: ", "at least one dynamic [[body]]"));
}

} // namespace
} // namespace tumble::scenario
