// [[spawn]]: many bodies from one seeded description, the same on every machine, and bad values
// rejected at load time with the file, line and key.
#include "tumble/scenario/random_draws.hpp"
#include "tumble/scenario/scenario.hpp"

#include "scenario/expect_scenario_error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace tumble::scenario {
namespace {

using test_support::failsWith;

std::string spawnScene(const std::string& spawnLines)
{
    return "[ground]\nheight = 0.0\n[[spawn]]\n" + spawnLines;
}

const std::string kS4Spawn = R"(count = 1000
seed = 1
spacing = 10.0
size = [2, 6, 2]
mass = 2.0
height = [4.0, 10.0]
orientation = "random"
angular_speed = [0.0, 2.0]
velocity = [0, 0, 0]
elasticity = 0.6
friction = 0.5
)";

TEST(RandomDraws, MapsTheStandardsGeneratorOutputToTheUnitInterval)
{
    // The C++ standard fixes std::mt19937_64's output: for the default seed 5489 its first value
    // is 14514284786278117030 ([rand.predef] gives the 10000th). unit() keeps the top 53 bits.
    RandomDraws draws(std::mt19937_64::default_seed);
    EXPECT_EQ(draws.unit(), static_cast<Real>(14514284786278117030ull >> 11) * 0x1.0p-53);
    std::mt19937_64 reference(std::mt19937_64::default_seed);
    reference.discard(9999);
    EXPECT_EQ(reference(), 9981545732273789042ull);
}

TEST(RandomDraws, RotationsAndDirectionsAreUniform)
{
    // For a uniform rotation R, R e is uniform on the sphere: each component of the mean of N
    // such vectors has mean 0 and standard deviation sqrt(1 / (3 N)); so has the mean direction.
    // The test allows 5 standard deviations.
    RandomDraws draws(7);
    constexpr int kCount = 20000;
    Vec3 meanAxis(0.0);
    Vec3 meanDirection(0.0);
    Real meanSquareZ = 0.0;
    for (int i = 0; i < kCount; ++i) {
        const Quat q = draws.rotation();
        ASSERT_NEAR(glm::length(q), 1.0, 1e-15);
        const Vec3 axis = q * Vec3(0, 1, 0);
        const Vec3 direction = draws.direction();
        ASSERT_NEAR(glm::length(direction), 1.0, 1e-15);
        meanAxis += axis / Real(kCount);
        meanDirection += direction / Real(kCount);
        meanSquareZ += axis.z * axis.z / Real(kCount);
    }
    const Real sigma = std::sqrt(1.0 / (3.0 * kCount));
    for (int k = 0; k < 3; ++k) {
        EXPECT_LT(std::abs(meanAxis[k]), 5.0 * sigma) << k;
        EXPECT_LT(std::abs(meanDirection[k]), 5.0 * sigma) << k;
    }
    // <z^2> = 1/3 on the sphere; its variance per sample is <z^4> - 1/9 = 1/5 - 1/9 = 4/45.
    EXPECT_NEAR(meanSquareZ, 1.0 / 3.0, 5.0 * std::sqrt(4.0 / 45.0 / kCount));
}

TEST(Spawn, PlacesCountBodiesOnASquareGridWithDrawsInTheirRanges)
{
    const Scenario scenario = parseScenario(spawnScene(kS4Spawn), "scene.toml");
    ASSERT_EQ(scenario.bodies.size(), 1000u);
    ASSERT_EQ(scenario.spawns.size(), 1u);
    // ceil(sqrt(1000)) = 32 columns, centred on the origin: x = (k mod 32 - 15.5) 10.
    EXPECT_EQ(scenario.bodies[0].name, "spawn1_1");
    EXPECT_DOUBLE_EQ(scenario.bodies[0].def.position.x, -155.0);
    EXPECT_DOUBLE_EQ(scenario.bodies[0].def.position.z, -155.0);
    EXPECT_DOUBLE_EQ(scenario.bodies[33].def.position.x, -145.0);
    EXPECT_DOUBLE_EQ(scenario.bodies[33].def.position.z, -145.0);
    for (const BodySpec& body : scenario.bodies) {
        EXPECT_EQ(body.def.mass, 2.0);
        EXPECT_EQ(body.def.shape.size, Vec3(2, 6, 2));
        EXPECT_EQ(body.def.material.restitution, 0.6);
        EXPECT_EQ(body.def.material.friction, 0.5);
        EXPECT_GE(body.def.position.y, 4.0);
        EXPECT_LE(body.def.position.y, 10.0);
        EXPECT_LE(glm::length(body.def.angularVelocity), 2.0);
        EXPECT_NEAR(glm::length(body.def.orientation), 1.0, 1e-15);
    }
}

TEST(Spawn, SameSeedSameBodiesOtherSeedOtherBodies)
{
    const Scenario first = parseScenario(spawnScene(kS4Spawn), "a.toml");
    const Scenario again = parseScenario(spawnScene(kS4Spawn), "b.toml");
    const std::vector<std::string> seed2{"spawn[0].seed=2"};
    const Scenario other = parseScenario(spawnScene(kS4Spawn), "c.toml", seed2);
    int differing = 0;
    for (std::size_t i = 0; i < first.bodies.size(); ++i) {
        EXPECT_EQ(first.bodies[i].def.position, again.bodies[i].def.position);
        EXPECT_EQ(first.bodies[i].def.orientation, again.bodies[i].def.orientation);
        EXPECT_EQ(first.bodies[i].def.angularVelocity, again.bodies[i].def.angularVelocity);
        differing += first.bodies[i].def.position.y != other.bodies[i].def.position.y ? 1 : 0;
    }
    EXPECT_EQ(differing, 1000);
}

TEST(Spawn, DrawsFollowTheDocumentedOrder)
{
    // Per body: height, orientation (3 numbers), angular speed, axis (2): the first body's
    // height is the first number of the stream, the second body's the seventh.
    const Scenario scenario = parseScenario(spawnScene(kS4Spawn), "scene.toml");
    RandomDraws draws(1);
    EXPECT_EQ(scenario.bodies[0].def.position.y, draws.uniform(4.0, 10.0));
    const Quat orientation = draws.rotation();
    EXPECT_EQ(scenario.bodies[0].def.orientation, orientation);
    const Real speed = draws.uniform(0.0, 2.0);
    EXPECT_EQ(scenario.bodies[0].def.angularVelocity, speed * draws.direction());
    EXPECT_EQ(scenario.bodies[1].def.position.y, draws.uniform(4.0, 10.0));
}

TEST(Spawn, CountCanBeOverriddenAndBodiesAddToTheNamedOnes)
{
    const std::vector<std::string> overrides{"spawn[0].count=5"};
    const Scenario scenario = parseScenario(
        "[[body]]\nname = \"die\"\nposition = [0, 5, 0]\n" + spawnScene(kS4Spawn), "scene.toml",
        overrides);
    ASSERT_EQ(scenario.bodies.size(), 6u);
    EXPECT_EQ(scenario.bodies[0].name, "die");
    EXPECT_EQ(scenario.bodies[5].name, "spawn1_5");
}

TEST(Spawn, FixedOrientationAndDefaultSpacing)
{
    const Scenario scenario = parseScenario(
        spawnScene("count = 4\nheight = [2, 2]\norientation = { axis = [0, 0, 1], degrees = 90 }\n"),
        "scene.toml");
    ASSERT_EQ(scenario.bodies.size(), 4u);
    // The default cube 2 x 2 x 2: neighbours one diagonal, 2 sqrt(3) m, apart.
    EXPECT_NEAR(scenario.bodies[1].def.position.x - scenario.bodies[0].def.position.x,
                2.0 * std::sqrt(3.0), 1e-15);
    for (const BodySpec& body : scenario.bodies) {
        EXPECT_NEAR(body.def.orientation.w, std::sqrt(0.5), 1e-15);
        EXPECT_EQ(body.def.position.y, 2.0);
        EXPECT_EQ(body.def.angularVelocity, Vec3(0.0));
    }
}

TEST(SpawnErrors, BadValuesNameTheLineAndKey)
{
    EXPECT_TRUE(failsWith(spawnScene("height = [4, 10]\n"), "scene.toml:3: spawn[0].count: ",
                          "missing"));
    EXPECT_TRUE(failsWith(spawnScene("count = 0\nheight = [4, 10]\n"),
                          "scene.toml:4: spawn[0].count: ", "between 1"));
    EXPECT_TRUE(failsWith(spawnScene("count = 2.5\nheight = [4, 10]\n"),
                          "scene.toml:4: spawn[0].count: ", "integer"));
    EXPECT_TRUE(failsWith(spawnScene("count = 3\nheight = [10, 4]\n"),
                          "scene.toml:5: spawn[0].height: ", "low must not exceed high"));
    EXPECT_TRUE(failsWith(spawnScene("count = 3\nheight = [0.5, 4]\n"),
                          "scene.toml:5: spawn[0].height: ", "inside the ground"));
    EXPECT_TRUE(failsWith(spawnScene("count = 3\nheight = [4]\n"),
                          "scene.toml:5: spawn[0].height: ", "[low, high]"));
    EXPECT_TRUE(failsWith(spawnScene("count = 3\nheight = [4, 5]\norientation = \"randm\"\n"),
                          "scene.toml:6: spawn[0].orientation: ", "\"random\""));
    EXPECT_TRUE(failsWith(spawnScene("count = 3\nheight = [4, 5]\nangular_speed = [-1, 2]\n"),
                          "scene.toml:6: spawn[0].angular_speed: ", ">= 0"));
    EXPECT_TRUE(failsWith(spawnScene("count = 3\nheight = [4, 5]\nangular_speed = [1, 500]\n"),
                          "scene.toml:6: spawn[0].angular_speed: ", "one step"));
    EXPECT_TRUE(failsWith(spawnScene("count = 3\nheight = [4, 5]\nmass = -2\n"),
                          "scene.toml:6: spawn[0].mass: ", "must be > 0"));
    EXPECT_TRUE(failsWith(spawnScene("count = 3\nheight = [4, 5]\nsize = [1, 0, 1]\n"),
                          "scene.toml:6: spawn[0].size", ""));
    EXPECT_TRUE(failsWith(spawnScene("count = 3\nheight = [4, 5]\nseed = -1\n"),
                          "scene.toml:6: spawn[0].seed: ", ">= 0"));
    EXPECT_TRUE(failsWith(spawnScene("count = 3\nheight = [4, 5]\nspacing = nan\n"),
                          "scene.toml:6: spawn[0].spacing: ", ""));
    EXPECT_TRUE(failsWith(spawnScene("count = 3\nheight = [4, 5]\ncolor = 1\n"),
                          "scene.toml:6: spawn[0].color: ", "unknown key"));
    EXPECT_TRUE(failsWith(spawnScene("count = 1000000\nheight = [4, 5]\nspacing = 5000\n"),
                          "scene.toml:3: spawn[0].spacing: ", "farthest"));
    // the default 2 m cube's diagonal is 3.46 m: closer neighbours could start inside each other
    EXPECT_TRUE(failsWith(spawnScene("count = 3\nheight = [4, 5]\nspacing = 3\n"),
                          "scene.toml:6: spawn[0].spacing: ", "at least the body's diagonal"));
}

TEST(SpawnErrors, SpawnedBodiesMustStartClearOfOtherBodiesAndPlanes)
{
    // issue 15: a dynamic body that starts inside another body or static geometry is exit 2 with
    // the file, line and key, spawned or not. Nine 0.5 m cubes 0.87 m apart around x = z = 0 at
    // heights 1 to 2: the middle one is inside a wall through the origin
    const std::string nine = "count = 9\nsize = [0.5, 0.5, 0.5]\nheight = [1, 2]\n";
    const std::string wall = "[[body]]\nname = \"wall\"\nmotion = \"static\"\n"
                             "size = [0.2, 2, 4]\nposition = [0, 1, 0]\n";
    EXPECT_TRUE(failsWith("[ground]\nheight = 0.0\n" + wall + "[[spawn]]\n" + nine,
                          "scene.toml:8: spawn[0]: ", "inside body \"wall\""));
    const std::string ramp = "[[plane]]\npoint = [0, 1.5, 0]\nnormal = [1, 1, 0]\n";
    EXPECT_TRUE(failsWith("[ground]\nheight = 0.0\n" + ramp + "[[spawn]]\n" + nine,
                          "scene.toml:6: spawn[0]: ", "inside plane[0]"));
    // two spawns share the grid's centre: their middle bodies meet
    EXPECT_TRUE(failsWith("[ground]\nheight = 0.0\n[[spawn]]\n" + nine + "[[spawn]]\n" + nine,
                          "scene.toml:7: spawn[1]: ", "inside body \"spawn1_"));
    // apart in height, the same two spawns load
    EXPECT_NO_THROW((void)parseScenario("[ground]\nheight = 0.0\n[[spawn]]\n" + nine +
                                            "[[spawn]]\ncount = 9\nsize = [0.5, 0.5, 0.5]\n"
                                            "height = [3, 4]\n",
                                        "s.toml"));
}

TEST(SpawnErrors, ASceneNeedsABodyOrASpawn)
{
    EXPECT_TRUE(failsWith("[ground]\nheight = 0\n", "scene.toml: body: ",
                          "at least one [[body]] or [[spawn]]"));
    EXPECT_NO_THROW((void)parseScenario(spawnScene("count = 1\nheight = [4, 5]\n"), "s.toml"));
}

} // namespace
} // namespace tumble::scenario
