// Reading scenario files: every shipped file loads, and values and defaults map onto the
// library's types (bad input: scenario_toml_errors_test.cpp).
#include "tumble/scenario/scenario.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

namespace tumble::scenario {
namespace {

const std::filesystem::path kScenarioDir = TUMBLE_SCENARIO_DIR;

void expectVecNear(const Vec3& actual, const Vec3& expected, Real tolerance = 1e-12)
{
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

void expectQuatNear(const Quat& actual, const Quat& expected, Real tolerance = 1e-12)
{
    EXPECT_NEAR(actual.w, expected.w, tolerance);
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

const BodySpec& bodyNamed(const Scenario& scenario, const std::string& name)
{
    const auto found = std::find_if(scenario.bodies.begin(), scenario.bodies.end(),
                                    [&](const BodySpec& body) { return body.name == name; });
    if (found == scenario.bodies.end()) {
        throw std::runtime_error("no body " + name);
    }
    return *found;
}

// --- The shipped scenario files ---------------------------------------------------------------

TEST(ScenarioToml, EveryScenarioFileLoadsAndBuilds)
{
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(kScenarioDir)) {
        if (entry.path().extension() == ".toml") {
            files.push_back(entry.path());
        }
    }
    ASSERT_GE(files.size(), 10u) << "scenario files in " << kScenarioDir;
    for (const std::filesystem::path& file : files) {
        SCOPED_TRACE(file.string());
        Scenario scenario;
        ASSERT_NO_THROW(scenario = loadScenario(file));
        EXPECT_EQ(scenario.sourceName, file.string());
        EXPECT_FALSE(scenario.bodies.empty());
        EXPECT_GT(scenario.dt, 0.0);
        const BuiltWorld built = buildWorld(scenario);
        EXPECT_EQ(built.bodies.size(), scenario.bodies.size());
    }
}

TEST(ScenarioToml, Part2ImpulseFileHasTheSixHandoutCases)
{
    const Scenario scenario = loadScenario(kScenarioDir / "part2_task2_impulses.toml");
    ASSERT_EQ(scenario.bodies.size(), 6u);
    ASSERT_EQ(scenario.impulses.size(), 6u);
    EXPECT_EQ(scenario.settings.gravity, Vec3(0.0));
    EXPECT_FALSE(scenario.ground.has_value());
    for (const BodySpec& body : scenario.bodies) {
        EXPECT_EQ(body.def.shape.size, Vec3(2.0, 6.0, 2.0)) << body.name;
        EXPECT_EQ(body.def.mass, 1.0) << body.name;
    }
    EXPECT_EQ(bodyNamed(scenario, "stop_all").def.linearVelocity, Vec3(3.0, 0.0, 0.0));
    EXPECT_EQ(bodyNamed(scenario, "stop_all").def.angularVelocity, Vec3(0.0, 0.0, 1.0));
    for (const ImpulseSpec& impulse : scenario.impulses) {
        EXPECT_EQ(impulse.at, 2.0);
        EXPECT_TRUE(impulse.isTarget()) << impulse.label;
        if (impulse.body == "left_spin") {
            EXPECT_EQ(*impulse.targetAngularVelocity, Vec3(0.0, 0.0, 0.5));
        }
        if (impulse.body == "stop_spin") {
            EXPECT_EQ(*impulse.targetVelocity, Vec3(0.0));
            EXPECT_EQ(*impulse.targetAngularVelocity, Vec3(0.0, 0.0, -0.5));
        }
    }
}

TEST(ScenarioToml, Part3ImpulseFileMatchesTheHandout)
{
    const Scenario scenario = loadScenario(kScenarioDir / "part3_task1_impulse.toml");
    EXPECT_EQ(scenario.dt, 1.0 / 240.0);
    ASSERT_EQ(scenario.bodies.size(), 1u);
    const BodyDef& def = scenario.bodies[0].def;
    EXPECT_EQ(def.mass, 2.0);
    EXPECT_EQ(def.shape.size, Vec3(2.0, 6.0, 2.0));
    EXPECT_EQ(def.linearVelocity, Vec3(2.0, 0.0, 0.0));
    ASSERT_EQ(scenario.impulses.size(), 1u);
    EXPECT_EQ(*scenario.impulses[0].targetVelocity, Vec3(0.0));
    EXPECT_EQ(*scenario.impulses[0].targetAngularVelocity, Vec3(0.0, 0.0, -0.6));
}

TEST(ScenarioToml, Part2CollisionFileUsesTheHandoutResponse)
{
    const Scenario scenario = loadScenario(kScenarioDir / "part2_task3_collision.toml");
    EXPECT_EQ(scenario.settings.response, ContactResponse::Average);
    ASSERT_TRUE(scenario.ground.has_value());
    EXPECT_EQ(scenario.ground->height, 0.0);
    EXPECT_EQ(scenario.bodies[0].def.material.friction, 0.0);
    expectQuatNear(scenario.bodies[0].def.orientation,
                   axisAngle(Vec3(0.0, 0.0, 1.0), std::numbers::pi / 6.0));
}

// --- Values and defaults ----------------------------------------------------------------------

TEST(ScenarioToml, EmptyBodyGetsEveryDefault)
{
    const Scenario scenario = parseScenario("[[body]]\n", "scene.toml");
    const WorldSettings defaults{};
    EXPECT_EQ(scenario.sourceName, "scene.toml");
    EXPECT_EQ(scenario.dt, 1.0 / 240.0);
    EXPECT_EQ(scenario.duration, 10.0);
    EXPECT_EQ(scenario.settings.gravity, Vec3(0.0, -9.81, 0.0));
    EXPECT_EQ(scenario.settings.integrator, Integrator::Exact);
    EXPECT_EQ(scenario.settings.response, ContactResponse::Sequential);
    EXPECT_EQ(scenario.settings.contactTolerance, defaults.contactTolerance);
    EXPECT_EQ(scenario.settings.restitutionThreshold, defaults.restitutionThreshold);
    EXPECT_EQ(scenario.settings.solverIterations, defaults.solverIterations);
    EXPECT_EQ(scenario.settings.allowSleep, defaults.allowSleep);
    EXPECT_EQ(scenario.settings.sleepTime, defaults.sleepTime);
    EXPECT_FALSE(scenario.ground.has_value());
    EXPECT_TRUE(scenario.impulses.empty());

    ASSERT_EQ(scenario.bodies.size(), 1u);
    const BodySpec& body = scenario.bodies[0];
    EXPECT_EQ(body.name, "body1");
    EXPECT_EQ(body.where.file, "scene.toml");
    EXPECT_EQ(body.where.line, 1);
    EXPECT_EQ(body.def.mass, 1.0);
    EXPECT_EQ(body.def.shape.size, Vec3(2.0, 2.0, 2.0));
    EXPECT_EQ(body.def.position, Vec3(0.0));
    EXPECT_EQ(body.def.orientation, Quat(1.0, 0.0, 0.0, 0.0));
    EXPECT_EQ(body.def.linearVelocity, Vec3(0.0));
    EXPECT_EQ(body.def.angularVelocity, Vec3(0.0));
    EXPECT_EQ(body.def.material.restitution, 0.6);
    EXPECT_EQ(body.def.material.friction, 0.5);
    EXPECT_FALSE(body.def.material.staticFriction.has_value());
}

TEST(ScenarioToml, WorldKeysMapOntoSettings)
{
    const Scenario scenario = parseScenario("[world]\n"
                                            "gravity = [0, -1.62, 0]\n"
                                            "dt = 0.001\n"
                                            "duration = 3\n"
                                            "integrator = \"handout\"\n"
                                            "response = \"average\"\n"
                                            "contact_tolerance = 1e-3\n"
                                            "restitution_threshold = 0\n"
                                            "solver_iterations = 8\n"
                                            "sleep = false\n"
                                            "sleep_linear_speed = 0.01\n"
                                            "sleep_angular_speed = 0.02\n"
                                            "sleep_time = 1.5\n"
                                            "[ground]\n"
                                            "height = -2\n"
                                            "[[body]]\n",
                                            "scene.toml");
    const WorldSettings& settings = scenario.settings;
    EXPECT_EQ(settings.gravity, Vec3(0.0, -1.62, 0.0));
    EXPECT_EQ(scenario.dt, 0.001);
    EXPECT_EQ(scenario.duration, 3.0);
    EXPECT_EQ(settings.integrator, Integrator::Handout);
    EXPECT_EQ(settings.response, ContactResponse::Average);
    EXPECT_EQ(settings.contactTolerance, 1e-3);
    EXPECT_EQ(settings.restitutionThreshold, 0.0);
    EXPECT_EQ(settings.solverIterations, 8);
    EXPECT_FALSE(settings.allowSleep);
    EXPECT_EQ(settings.sleepLinearSpeed, 0.01);
    EXPECT_EQ(settings.sleepAngularSpeed, 0.02);
    EXPECT_EQ(settings.sleepTime, 1.5);
    ASSERT_TRUE(scenario.ground.has_value());
    EXPECT_EQ(scenario.ground->height, -2.0);
}

TEST(ScenarioToml, SoftStepKeysMapOntoSettings)
{
    const Scenario scenario = parseScenario("[world]\n"
                                            "solver = \"soft\"\n"
                                            "soft_substeps = 8\n"
                                            "soft_contact_hertz = 45\n"
                                            "soft_damping_ratio = 2\n"
                                            "soft_push_speed = 0.5\n"
                                            "[[body]]\n",
                                            "scene.toml");
    const WorldSettings& settings = scenario.settings;
    EXPECT_EQ(settings.solver, ContactSolver::Soft);
    EXPECT_EQ(settings.softSubsteps, 8);
    EXPECT_EQ(settings.softContactHertz, 45.0);
    EXPECT_EQ(settings.softDampingRatio, 2.0);
    EXPECT_EQ(settings.softPushSpeed, 0.5);
    EXPECT_EQ(parseScenario("[[body]]\n", "scene.toml").settings.solver, ContactSolver::Exact);
}

TEST(ScenarioToml, EmptyGroundTableIsThePlaneAtZero)
{
    const Scenario scenario =
        parseScenario("[ground]\n[[body]]\nposition = [0, 1, 0]\n", "scene.toml");
    ASSERT_TRUE(scenario.ground.has_value());
    EXPECT_EQ(scenario.ground->height, 0.0);
}

TEST(ScenarioToml, BodyKeysMapOntoBodyDef)
{
    const Scenario scenario = parseScenario("[[body]]\n"
                                            "name = \"rb\"\n"
                                            "size = [1, 2, 3]\n"
                                            "mass = 2\n"
                                            "position = [1, 5, -1]\n"
                                            "velocity = [1, 0, 0.5]\n"
                                            "angular_velocity = [1, 0.5, 2]\n"
                                            "elasticity = 0.25\n"
                                            "friction = 0.3\n"
                                            "static_friction = 0.4\n",
                                            "scene.toml");
    const BodySpec& body = scenario.bodies.at(0);
    EXPECT_EQ(body.name, "rb");
    EXPECT_EQ(body.def.shape.size, Vec3(1.0, 2.0, 3.0));
    EXPECT_EQ(body.def.mass, 2.0); // an integer where a float is expected
    EXPECT_EQ(body.def.position, Vec3(1.0, 5.0, -1.0));
    EXPECT_EQ(body.def.linearVelocity, Vec3(1.0, 0.0, 0.5));
    EXPECT_EQ(body.def.angularVelocity, Vec3(1.0, 0.5, 2.0));
    EXPECT_EQ(body.def.material.restitution, 0.25);
    EXPECT_EQ(body.def.material.friction, 0.3);
    ASSERT_TRUE(body.def.material.staticFriction.has_value());
    EXPECT_EQ(*body.def.material.staticFriction, 0.4);
}

TEST(ScenarioToml, ScaleMultipliesTheDefaultCube)
{
    const Scenario scenario = parseScenario("[[body]]\nscale = [1, 3, 1]\n", "scene.toml");
    EXPECT_EQ(scenario.bodies[0].def.shape.size, Vec3(2.0, 6.0, 2.0));
}

TEST(ScenarioToml, AxisAngleOrientationIsTheMatchingQuaternion)
{
    // The axis need not be unit length; 30 degrees about z is (cos 15, 0, 0, sin 15).
    const Scenario scenario =
        parseScenario("[[body]]\norientation = { axis = [0, 0, 2], degrees = 30 }\n", "scene.toml");
    const Quat& q = scenario.bodies[0].def.orientation;
    const Real half = std::numbers::pi / 12.0;
    expectQuatNear(q, Quat(std::cos(half), 0.0, 0.0, std::sin(half)));
    // It turns x towards y: (1, 0, 0) -> (cos 30, sin 30, 0).
    expectVecNear(q * Vec3(1.0, 0.0, 0.0), Vec3(std::sqrt(3.0) / 2.0, 0.5, 0.0));
}

TEST(ScenarioToml, NearlyUnitQuaternionIsNormalised)
{
    const Scenario scenario =
        parseScenario("[[body]]\norientation = [0.5, 0.5, 0.5, 0.5000004]\n", "scene.toml");
    const Quat& q = scenario.bodies[0].def.orientation;
    EXPECT_NEAR(glm::length(q), 1.0, 1e-15);
    EXPECT_NEAR(q.w, 0.5, 1e-6);
    EXPECT_GT(q.z, q.w);
}

TEST(ScenarioToml, UnnamedBodiesAreNumberedFromOne)
{
    const Scenario scenario =
        parseScenario("[[body]]\n[[body]]\nname = \"rb\"\nposition = [3, 0, 0]\n[[body]]\n"
                      "position = [6, 0, 0]\n",
                      "scene.toml");
    ASSERT_EQ(scenario.bodies.size(), 3u);
    EXPECT_EQ(scenario.bodies[0].name, "body1");
    EXPECT_EQ(scenario.bodies[1].name, "rb");
    EXPECT_EQ(scenario.bodies[2].name, "body3");
    EXPECT_EQ(scenario.bodies[2].where.line, 5);
}

TEST(ScenarioToml, ImpulsesAreSortedByTimeKeepingFileOrderForTies)
{
    const Scenario scenario = parseScenario("[[body]]\nname = \"rb\"\n"
                                            "[[impulse]]\nat = 3.0\nbody = \"rb\"\n"
                                            "impulse = [1, 0, 0]\n"
                                            "[[impulse]]\nat = 1.0\nbody = \"rb\"\n"
                                            "impulse = [0, 1, 0]\noffset = [0, 0, 1]\n"
                                            "[[impulse]]\nat = 3\nbody = \"rb\"\n"
                                            "velocity = [0, 0, 0]\n"
                                            "angular_velocity = [0, 0, -0.6]\n",
                                            "scene.toml");
    ASSERT_EQ(scenario.impulses.size(), 3u);
    EXPECT_EQ(scenario.impulses[0].label, "impulse[1]");
    EXPECT_EQ(scenario.impulses[1].label, "impulse[0]");
    EXPECT_EQ(scenario.impulses[2].label, "impulse[2]");
    EXPECT_EQ(scenario.impulses[0].at, 1.0);
    EXPECT_EQ(scenario.impulses[0].where.line, 7);

    const ImpulseSpec& direct = scenario.impulses[1];
    EXPECT_FALSE(direct.isTarget());
    EXPECT_EQ(direct.body, "rb");
    EXPECT_EQ(*direct.impulse, Vec3(1.0, 0.0, 0.0));
    ASSERT_TRUE(direct.offset.has_value()) << "offset defaults to the centre of mass";
    EXPECT_EQ(*direct.offset, Vec3(0.0));
    EXPECT_EQ(*scenario.impulses[0].offset, Vec3(0.0, 0.0, 1.0));

    const ImpulseSpec& target = scenario.impulses[2];
    EXPECT_TRUE(target.isTarget());
    EXPECT_FALSE(target.impulse.has_value());
    EXPECT_EQ(*target.targetVelocity, Vec3(0.0));
    EXPECT_EQ(*target.targetAngularVelocity, Vec3(0.0, 0.0, -0.6));
}

} // namespace
} // namespace tumble::scenario
