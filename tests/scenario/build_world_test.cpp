// buildWorld: the World gets the scenario's settings, ground and bodies, with the mass properties
// the handouts compute.
#include "tumble/scenario/scenario.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

namespace tumble::scenario {
namespace {

void expectMatNear(const Mat3& actual, const Mat3& expected, Real tolerance)
{
    for (int column = 0; column < 3; ++column) {
        for (int row = 0; row < 3; ++row) {
            EXPECT_NEAR(actual[column][row], expected[column][row], tolerance)
                << "element (" << row << ", " << column << ")";
        }
    }
}

TEST(BuildWorld, HandoutCuboidHasTheHandoutInverseInertia)
{
    // Part 3, Task 1: 2 x 6 x 2, mass 2. I0 = m/12 diag(h^2 + d^2, w^2 + d^2, w^2 + h^2)
    // = diag(20/3, 4/3, 20/3), so I0^-1 = diag(0.15, 0.75, 0.15).
    const Scenario scenario =
        loadScenario(std::filesystem::path(TUMBLE_SCENARIO_DIR) / "part3_task1_impulse.toml");
    const BuiltWorld built = buildWorld(scenario);
    ASSERT_EQ(built.bodies.size(), 1u);
    const Body& body = built.world.body(built.bodies[0]);
    EXPECT_EQ(body.mass, 2.0);
    EXPECT_DOUBLE_EQ(body.invMass, 0.5);
    EXPECT_EQ(body.shape.size, Vec3(2.0, 6.0, 2.0));
    EXPECT_NEAR(body.invInertiaBody.x, 0.15, 1e-12);
    EXPECT_NEAR(body.invInertiaBody.y, 0.75, 1e-12);
    EXPECT_NEAR(body.invInertiaBody.z, 0.15, 1e-12);
    // Unrotated, the world-frame inverse inertia is the same diagonal.
    expectMatNear(body.invInertiaWorld, Mat3(Vec3(0.15, 0, 0), Vec3(0, 0.75, 0), Vec3(0, 0, 0.15)),
                  1e-12);
    EXPECT_EQ(body.linearVelocity, Vec3(2.0, 0.0, 0.0));
}

TEST(BuildWorld, RotatedBodyHasRotatedInverseInertia)
{
    const Scenario scenario = parseScenario(
        "[[body]]\nscale = [1, 3, 1]\nmass = 2\norientation = { axis = [0, 0, 1], degrees = 90 }\n",
        "scene.toml");
    const BuiltWorld built = buildWorld(scenario);
    const Body& body = built.world.body(built.bodies[0]);
    // A quarter turn about z swaps the x and y axes of the body.
    expectMatNear(body.invInertiaWorld, Mat3(Vec3(0.75, 0, 0), Vec3(0, 0.15, 0), Vec3(0, 0, 0.15)),
                  1e-12);
}

TEST(BuildWorld, SettingsAndGroundReachTheWorld)
{
    const Scenario scenario = parseScenario("[world]\n"
                                            "gravity = [0, -1, 0]\n"
                                            "integrator = \"handout\"\n"
                                            "response = \"average\"\n"
                                            "solver_iterations = 7\n"
                                            "[ground]\n"
                                            "height = 0.25\n"
                                            "[[body]]\n"
                                            "position = [0, 1.25, 0]\n",
                                            "scene.toml");
    const BuiltWorld built = buildWorld(scenario);
    const WorldSettings& settings = built.world.settings();
    EXPECT_EQ(settings.gravity, Vec3(0.0, -1.0, 0.0));
    EXPECT_EQ(settings.integrator, Integrator::Handout);
    EXPECT_EQ(settings.response, ContactResponse::Average);
    EXPECT_EQ(settings.solverIterations, 7);
    ASSERT_TRUE(built.world.ground().has_value());
    EXPECT_EQ(built.world.ground()->height, 0.25);
    EXPECT_EQ(built.world.time(), 0.0);
}

TEST(BuildWorld, NoGroundTableMeansNoGround)
{
    const BuiltWorld built = buildWorld(parseScenario("[[body]]\n", "scene.toml"));
    EXPECT_FALSE(built.world.ground().has_value());
}

TEST(BuildWorld, BodiesAreCreatedInFileOrderWithTheirDefinitions)
{
    const Scenario scenario = parseScenario("[[body]]\n"
                                            "name = \"a\"\n"
                                            "position = [0, 5, 0]\n"
                                            "angular_velocity = [1, 0.5, 2]\n"
                                            "elasticity = 0.3\n"
                                            "friction = 0.2\n"
                                            "static_friction = 0.4\n"
                                            "[[body]]\n"
                                            "name = \"b\"\n"
                                            "size = [1, 2, 3]\n"
                                            "mass = 6\n"
                                            "position = [10, 1, 0]\n",
                                            "scene.toml");
    const BuiltWorld built = buildWorld(scenario);
    ASSERT_EQ(built.bodies.size(), 2u);
    EXPECT_EQ(built.world.bodyIds(), built.bodies);
    const Body& a = built.world.body(built.bodies[0]);
    EXPECT_EQ(a.position, Vec3(0.0, 5.0, 0.0));
    EXPECT_EQ(a.angularVelocity, Vec3(1.0, 0.5, 2.0));
    EXPECT_EQ(a.material.restitution, 0.3);
    EXPECT_EQ(a.material.friction, 0.2);
    EXPECT_EQ(a.material.staticFrictionOrKinetic(), 0.4);
    const Body& b = built.world.body(built.bodies[1]);
    EXPECT_EQ(b.position, Vec3(10.0, 1.0, 0.0));
    EXPECT_EQ(b.mass, 6.0);
    // I0 = 6/12 diag(4 + 9, 1 + 9, 1 + 4).
    EXPECT_NEAR(b.invInertiaBody.x, 1.0 / 6.5, 1e-12);
    EXPECT_NEAR(b.invInertiaBody.y, 1.0 / 5.0, 1e-12);
    EXPECT_NEAR(b.invInertiaBody.z, 1.0 / 2.5, 1e-12);
}

TEST(BuildWorld, HandMadeScenarioWithABadBodyIsReportedNotAsserted)
{
    Scenario scenario;
    scenario.sourceName = "by hand";
    BodySpec spec;
    spec.name = "rb";
    spec.def.mass = 0.0;
    spec.where = SourceLocation{"by hand", 0};
    scenario.bodies.push_back(spec);
    try {
        (void)buildWorld(scenario);
        FAIL() << "built a body of mass 0";
    } catch (const ScenarioError& error) {
        EXPECT_EQ(error.key(), "rb.mass");
        EXPECT_EQ(std::string(error.what()), "by hand: rb.mass: must be positive and finite");
    }
}

TEST(BuildWorld, WorldStepsAfterBuilding)
{
    // A smoke test that the built World is usable: one free-fall step moves the body down.
    const Scenario scenario = parseScenario("[[body]]\nposition = [0, 10, 0]\n", "scene.toml");
    BuiltWorld built = buildWorld(scenario);
    built.world.step(scenario.dt);
    EXPECT_LT(built.world.body(built.bodies[0]).position.y, 10.0);
    EXPECT_LT(built.world.body(built.bodies[0]).linearVelocity.y, 0.0);
}

} // namespace
} // namespace tumble::scenario
