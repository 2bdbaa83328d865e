// --set overrides: applied to the TOML before validation, by world/ground/body/impulse key; a bad
// override is reported against "--set" and its KEY.
#include "tumble/scenario/scenario.hpp"

#include "scenario/expect_scenario_error.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace tumble::scenario {
namespace {

using test_support::failsWith;

constexpr std::string_view kScene = "[world]\n"
                                    "dt = 0.01\n"
                                    "[[body]]\n"
                                    "name = \"rb\"\n"
                                    "scale = [1, 3, 1]\n"
                                    "mass = 2\n"
                                    "[[impulse]]\n"
                                    "at = 2.0\n"
                                    "body = \"rb\"\n"
                                    "velocity = [0, 0, 0]\n"
                                    "angular_velocity = [0, 0, -0.6]\n";

Scenario withOverrides(std::vector<std::string> overrides, std::string_view text = kScene)
{
    return parseScenario(text, "scene.toml", overrides);
}

TEST(Overrides, SetWorldValues)
{
    const Scenario scenario = withOverrides(
        {"world.dt=0.001", "world.gravity=[0, 0, 0]", "world.duration = 2", "world.sleep=false"});
    EXPECT_EQ(scenario.dt, 0.001);
    EXPECT_EQ(scenario.settings.gravity, Vec3(0.0));
    EXPECT_EQ(scenario.duration, 2.0);
    EXPECT_FALSE(scenario.settings.allowSleep);
}

TEST(Overrides, CreateTheWorldTableWhenAbsent)
{
    const Scenario scenario = withOverrides({"world.response=average"}, "[[body]]\n");
    EXPECT_EQ(scenario.settings.response, ContactResponse::Average);
}

TEST(Overrides, BareWordIsAStringAndQuotedStringWorksToo)
{
    EXPECT_EQ(withOverrides({"world.integrator=handout"}).settings.integrator, Integrator::Handout);
    EXPECT_EQ(withOverrides({"world.integrator=\"handout\""}).settings.integrator,
              Integrator::Handout);
}

TEST(Overrides, GroundHeightCreatesTheGround)
{
    const Scenario plain = withOverrides({});
    EXPECT_FALSE(plain.ground.has_value());
    // below the body, which may not start inside the ground (issue 14, item 9)
    const Scenario scenario = withOverrides({"ground.height=-3.5"});
    ASSERT_TRUE(scenario.ground.has_value());
    EXPECT_EQ(scenario.ground->height, -3.5);
}

TEST(Overrides, BodyByName)
{
    const Scenario scenario =
        withOverrides({"rb.elasticity=0.7", "rb.velocity=[1,2,3]", "rb.mass=5"});
    const BodyDef& def = scenario.bodies[0].def;
    EXPECT_EQ(def.material.restitution, 0.7);
    EXPECT_EQ(def.linearVelocity, Vec3(1.0, 2.0, 3.0));
    EXPECT_EQ(def.mass, 5.0);
}

TEST(Overrides, OrientationAsAnInlineTable)
{
    const Scenario scenario = withOverrides({"rb.orientation={ axis = [0, 0, 1], degrees = 90 }"});
    const Vec3 turned = scenario.bodies[0].def.orientation * Vec3(1.0, 0.0, 0.0);
    EXPECT_NEAR(turned.x, 0.0, 1e-12);
    EXPECT_NEAR(turned.y, 1.0, 1e-12);
}

TEST(Overrides, SizeReplacesScaleFromTheFile)
{
    const Scenario scenario = withOverrides({"rb.size=[1, 1, 1]"});
    EXPECT_EQ(scenario.bodies[0].def.shape.size, Vec3(1.0));
}

TEST(Overrides, SingleBodyAsBodyAndUnnamedBodyByDefaultName)
{
    EXPECT_EQ(withOverrides({"body.mass=3"}).bodies[0].def.mass, 3.0);
    const Scenario unnamed = withOverrides({"body2.friction=0.1"},
                                          "[[body]]\n[[body]]\nposition = [3, 0, 0]\n");
    EXPECT_EQ(unnamed.bodies[0].def.material.friction, 0.5);
    EXPECT_EQ(unnamed.bodies[1].def.material.friction, 0.1);
}

TEST(Overrides, ImpulseByIndexAndDirectImpulseReplacesTheTarget)
{
    const Scenario scenario = withOverrides(
        {"impulse[0].at=1.25", "impulse[0].impulse=[-4, 0, 0]", "impulse[0].offset=[0, -1, 0]"});
    ASSERT_EQ(scenario.impulses.size(), 1u);
    const ImpulseSpec& impulse = scenario.impulses[0];
    EXPECT_EQ(impulse.at, 1.25);
    EXPECT_FALSE(impulse.isTarget());
    EXPECT_EQ(*impulse.impulse, Vec3(-4.0, 0.0, 0.0));
    EXPECT_EQ(*impulse.offset, Vec3(0.0, -1.0, 0.0));
}

TEST(Overrides, AppliedBeforeValidationSoTheyCanRepairAValue)
{
    const Scenario scenario = withOverrides({"rb.mass=2"}, "[[body]]\nname = \"rb\"\nmass = -1\n");
    EXPECT_EQ(scenario.bodies[0].def.mass, 2.0);
}

TEST(Overrides, LaterOverrideWins)
{
    EXPECT_EQ(withOverrides({"world.dt=0.002", "world.dt=0.003"}).dt, 0.003);
}

TEST(Overrides, RenamedBodyIsFoundByItsNewName)
{
    const Scenario scenario =
        withOverrides({"rb.name=\"box\"", "box.mass=4", "impulse[0].body=box"});
    EXPECT_EQ(scenario.bodies[0].name, "box");
    EXPECT_EQ(scenario.bodies[0].def.mass, 4.0);
    EXPECT_EQ(scenario.impulses[0].body, "box");
}

TEST(Overrides, LoadScenarioAppliesThem)
{
    const std::vector<std::string> overrides{"rb.elasticity=0.7", "ground.height=0.5"};
    const Scenario scenario = loadScenario(
        std::filesystem::path(TUMBLE_SCENARIO_DIR) / "part3_task4_friction.toml", overrides);
    EXPECT_EQ(scenario.bodies[0].def.material.restitution, 0.7);
    EXPECT_EQ(scenario.ground->height, 0.5);
}

// --- Bad overrides ----------------------------------------------------------------------------

TEST(OverrideErrors, MissingEquals)
{
    const std::vector<std::string> overrides{"world.dt"};
    EXPECT_TRUE(failsWith(kScene, "--set: world.dt: ", "expected KEY=VALUE", overrides));
}

TEST(OverrideErrors, MissingValue)
{
    const std::vector<std::string> overrides{"world.dt="};
    EXPECT_TRUE(failsWith(kScene, "--set: world.dt: ", "missing value", overrides));
}

TEST(OverrideErrors, KeyWithoutSection)
{
    const std::vector<std::string> overrides{"dt=0.1"};
    EXPECT_TRUE(failsWith(kScene, "--set: dt: ", "expected world.<key>", overrides));
}

TEST(OverrideErrors, UnknownBody)
{
    const std::vector<std::string> overrides{"box.mass=1"};
    EXPECT_TRUE(
        failsWith(kScene, "--set: box.mass: ", "no body named 'box' (bodies: rb", overrides));
}

TEST(OverrideErrors, UnknownKeySuggestsTheClosest)
{
    const std::vector<std::string> overrides{"rb.elastcity=0.7"};
    EXPECT_TRUE(failsWith(kScene, "--set: rb.elastcity: ",
                          "unknown key 'elastcity' (did you mean 'elasticity'?)", overrides));
}

TEST(OverrideErrors, UnknownWorldKey)
{
    const std::vector<std::string> overrides{"world.gravityy=[0,0,0]"};
    EXPECT_TRUE(failsWith(kScene, "--set: world.gravityy: ", "did you mean 'gravity'?", overrides));
}

TEST(OverrideErrors, ImpulseIndexOutOfRange)
{
    const std::vector<std::string> overrides{"impulse[3].at=1"};
    EXPECT_TRUE(
        failsWith(kScene, "--set: impulse[3].at: ", "the scenario has 1 [[impulse]]", overrides));
}

TEST(OverrideErrors, ValueThatIsNotToml)
{
    const std::vector<std::string> overrides{"rb.velocity=[1, 2"};
    EXPECT_TRUE(failsWith(kScene, "--set: rb.velocity: ", "cannot read '[1, 2' as a TOML value",
                          overrides));
}

TEST(OverrideErrors, InvalidValueIsReportedAgainstTheOverride)
{
    const std::vector<std::string> overrides{"rb.mass=-1"};
    EXPECT_TRUE(failsWith(kScene, "--set: rb.mass: ", "must be > 0, got -1", overrides));
}

TEST(OverrideErrors, WrongTypeIsReportedAgainstTheOverride)
{
    const std::vector<std::string> overrides{"world.dt=fast"};
    EXPECT_TRUE(failsWith(kScene, "--set: world.dt: ", "expected a number, got a string (\"fast\")",
                          overrides));
}

TEST(OverrideErrors, BadEnumIsReportedAgainstTheOverride)
{
    const std::vector<std::string> overrides{"world.integrator=rk4"};
    EXPECT_TRUE(failsWith(
        kScene, "--set: world.integrator: ", "must be one of \"exact\", \"handout\"", overrides));
}

TEST(OverrideErrors, ProblemInsideAnOverriddenTableKeepsItsPath)
{
    const std::vector<std::string> overrides{"rb.orientation={ axis = [0, 0, 0], degrees = 5 }"};
    EXPECT_TRUE(
        failsWith(kScene, "--set: rb.orientation.axis: ", "must be a nonzero vector", overrides));
}

TEST(OverrideErrors, BadElementOfAnOverriddenArray)
{
    const std::vector<std::string> overrides{"world.gravity=[0, nan, 0]"};
    EXPECT_TRUE(failsWith(kScene, "--set: world.gravity[1]: ", "must be finite", overrides));
}

TEST(OverrideErrors, MoreThanOneValue)
{
    const std::vector<std::string> overrides{"world.dt=1\nduration = 3"};
    EXPECT_TRUE(failsWith(kScene, "--set: world.dt: ", "not a single TOML value", overrides));
}

} // namespace
} // namespace tumble::scenario
