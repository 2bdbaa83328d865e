// Reading scenario files: each kind of bad input throws a ScenarioError whose one-line message
// names the file, the line and the key.
#include "tumble/scenario/scenario.hpp"

#include "scenario/expect_scenario_error.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace tumble::scenario {
namespace {

using test_support::failsWith;
using test_support::parseError;

const std::filesystem::path kScenarioDir = TUMBLE_SCENARIO_DIR;

TEST(ScenarioTomlErrors, MissingFileNamesTheFile)
{
    const std::filesystem::path missing = kScenarioDir / "no_such_scenario.toml";
    try {
        (void)loadScenario(missing);
        FAIL() << "loaded a missing file";
    } catch (const ScenarioError& error) {
        const std::string message = error.what();
        EXPECT_TRUE(message.starts_with(missing.string() + ": ")) << message;
        EXPECT_NE(message.find("cannot open"), std::string::npos) << message;
        EXPECT_EQ(error.where().line, 0);
    }
}

TEST(ScenarioTomlErrors, DirectoryIsNotAScenario)
{
    EXPECT_THROW((void)loadScenario(kScenarioDir), ScenarioError);
}

TEST(ScenarioTomlErrors, SyntaxErrorGivesTheLine)
{
    EXPECT_TRUE(
        failsWith("[[body]]\nname = \"rb\"\nmass = \n", "scene.toml:3: ", "TOML syntax error"));
}

TEST(ScenarioTomlErrors, UnknownKeySuggestsTheClosestKnownOne)
{
    EXPECT_TRUE(failsWith("[[body]]\nname = \"rb\"\nelasticty = 0.5\n",
                          "scene.toml:3: body[0].elasticty: ",
                          "unknown key 'elasticty' (did you mean 'elasticity'?)"));
}

TEST(ScenarioTomlErrors, UnknownKeyFarFromAnyListsTheKnownKeys)
{
    EXPECT_TRUE(failsWith("[world]\ndt = 0.01\ncolour = 3\n[[body]]\n",
                          "scene.toml:3: world.colour: ", "known keys: gravity dt duration"));
}

TEST(ScenarioTomlErrors, UnknownTopLevelKey)
{
    EXPECT_TRUE(failsWith("mass = 2\n[[body]]\n", "scene.toml:1: mass: ", "unknown key 'mass'"));
}

TEST(ScenarioTomlErrors, UnknownKeyIsTheFirstInTheFile)
{
    EXPECT_TRUE(
        failsWith("[[body]]\nzzz = 1\naaa = 2\n", "scene.toml:2: body[0].zzz: ", "unknown key"));
}

TEST(ScenarioTomlErrors, UnknownGroundKey)
{
    EXPECT_TRUE(failsWith("[ground]\nheigth = 1\n[[body]]\n",
                          "scene.toml:2: ground.heigth: ", "(did you mean 'height'?)"));
}

TEST(ScenarioTomlErrors, UnknownKeyInAxisAngle)
{
    EXPECT_TRUE(
        failsWith("[[body]]\norientation = { axis = [0, 0, 1], degree = 30 }\n",
                  "scene.toml:2: body[0].orientation.degree: ", "(did you mean 'degrees'?)"));
}

TEST(ScenarioTomlErrors, StringWhereNumberExpected)
{
    EXPECT_TRUE(
        failsWith("[[body]]\nname = \"rb\"\nmass = \"heavy\"\n",
                  "scene.toml:3: body[0].mass: ", "expected a number, got a string (\"heavy\")"));
}

TEST(ScenarioTomlErrors, ArrayOfWrongLength)
{
    EXPECT_TRUE(failsWith("[[body]]\nposition = [1, 2]\n", "scene.toml:2: body[0].position: ",
                          "expected an array of 3 numbers [x, y, z], got an array of 2 values"));
}

TEST(ScenarioTomlErrors, WorldMustBeATable)
{
    EXPECT_TRUE(failsWith("world = 3\n[[body]]\n", "scene.toml:1: world: ", "expected a table"));
}

TEST(ScenarioTomlErrors, BodyMustBeAnArrayOfTables)
{
    EXPECT_TRUE(failsWith("[body]\nmass = 1\n",
                          "scene.toml:1: body: ", "expected an array of tables ([[body]])"));
}

TEST(ScenarioTomlErrors, NonPositiveMass)
{
    EXPECT_TRUE(failsWith("[[body]]\nname = \"rb\"\nmass = 0\n",
                          "scene.toml:3: body[0].mass: ", "must be > 0, got 0 (body \"rb\")"));
}

TEST(ScenarioTomlErrors, NonPositiveSize)
{
    EXPECT_TRUE(failsWith("[[body]]\nsize = [2, -6, 2]\n", "scene.toml:2: body[0].size: ",
                          "every component must be > 0, got [2, -6, 2]"));
}

TEST(ScenarioTomlErrors, NonPositiveScale)
{
    EXPECT_TRUE(failsWith("[[body]]\n\nscale = [1, 0, 1]\n",
                          "scene.toml:3: body[0].scale: ", "every component must be > 0"));
}

TEST(ScenarioTomlErrors, SizeAndScaleTogether)
{
    EXPECT_TRUE(failsWith("[[body]]\nsize = [2, 6, 2]\nscale = [1, 3, 1]\n",
                          "scene.toml:3: body[0].scale: ", "give size or scale, not both"));
}

TEST(ScenarioTomlErrors, NanValue)
{
    EXPECT_TRUE(failsWith("[[body]]\nmass = nan\n",
                          "scene.toml:2: body[0].mass: ", "must be finite, got nan"));
}

TEST(ScenarioTomlErrors, InfiniteVectorComponent)
{
    EXPECT_TRUE(failsWith("[[body]]\n\nvelocity = [0, -inf, 0]\n",
                          "scene.toml:3: body[0].velocity[1]: ", "must be finite, got -inf"));
}

// a vector whose squares overflow is reported with its length as written, not as inf
TEST(ScenarioTomlErrors, HugeVectorIsReportedWithItsOwnMagnitude)
{
    EXPECT_TRUE(failsWith("[[body]]\nposition = [0, 1e300, 0]\n", "scene.toml:2: body[0].position: ",
                          "must be at most 1e+06 m, got 1e+300"));
    EXPECT_TRUE(failsWith("[[body]]\nvelocity = [0, 0, -5e200]\n",
                          "scene.toml:2: body[0].velocity: ", "got 5e+200"));
    EXPECT_TRUE(failsWith("[[body]]\nangular_velocity = [0, 0, -1e300]\n",
                          "scene.toml:2: body[0].angular_velocity: ", "got 1e+300"));
    EXPECT_TRUE(failsWith("[world]\ngravity = [0, -1e300, 0]\n[[body]]\n",
                          "scene.toml:2: world.gravity: ", "got 1e+300"));
    EXPECT_TRUE(failsWith(
        "[[body]]\n[[impulse]]\nat = 0\nbody = \"body1\"\nimpulse = [1e308, 1e308, 1e308]\n",
        "scene.toml:5: impulse[0].impulse: ", "got 1.7320508"));
    EXPECT_TRUE(failsWith("[[spawn]]\ncount = 4\nspacing = 1e308\nheight = [1, 2]\n",
                          "scene.toml:3: spawn[0].spacing: ", "got 1e+308"));
    const std::optional<ScenarioError> error =
        parseError("[[body]]\nposition = [1e300, 1e300, 0]\n");
    ASSERT_TRUE(error.has_value());
    EXPECT_EQ(std::string(error->what()).find("inf"), std::string::npos) << error->what();
}

TEST(ScenarioTomlErrors, QuaternionFarFromUnitLength)
{
    EXPECT_TRUE(failsWith("[[body]]\norientation = [1, 0, 0, 0.1]\n",
                          "scene.toml:2: body[0].orientation: ", "not a unit quaternion"));
}

TEST(ScenarioTomlErrors, ZeroRotationAxis)
{
    EXPECT_TRUE(failsWith("[[body]]\norientation = { axis = [0, 0, 0], degrees = 30 }\n",
                          "scene.toml:2: body[0].orientation.axis: ", "must be a nonzero vector"));
}

TEST(ScenarioTomlErrors, AxisAngleWithoutDegrees)
{
    EXPECT_TRUE(failsWith("[[body]]\norientation = { axis = [0, 0, 1] }\n",
                          "scene.toml:2: body[0].orientation: ", "needs both axis and degrees"));
}

TEST(ScenarioTomlErrors, EmptyBodyName)
{
    EXPECT_TRUE(
        failsWith("[[body]]\nname = \"\"\n", "scene.toml:2: body[0].name: ", "must not be empty"));
}

TEST(ScenarioTomlErrors, DuplicateBodyNames)
{
    EXPECT_TRUE(
        failsWith("[[body]]\nname = \"rb\"\n[[body]]\nname = \"rb\"\n",
                  "scene.toml:4: body[1].name: ", "duplicate body name \"rb\" (also body[0])"));
}

TEST(ScenarioTomlErrors, LineBreakInQuotedTextKeepsTheMessageOnOneLine)
{
    EXPECT_TRUE(failsWith("[[body]]\nname = \"a\\nb\"\n[[body]]\nname = \"a\\nb\"\n",
                          "scene.toml:4: body[1].name: ", "duplicate body name \"a\\nb\""));
}

TEST(ScenarioTomlErrors, ExplicitNameClashingWithADefaultName)
{
    EXPECT_TRUE(failsWith("[[body]]\n[[body]]\nname = \"body1\"\n",
                          "scene.toml:3: body[1].name: ", "duplicate body name \"body1\""));
}

TEST(ScenarioTomlErrors, NoBody)
{
    EXPECT_TRUE(failsWith("[world]\ndt = 0.01\n",
                          "scene.toml: body: ", "a scenario needs at least one [[body]]"));
}

TEST(ScenarioTomlErrors, ImpulseOnUnknownBody)
{
    EXPECT_TRUE(failsWith("[[body]]\nname = \"rb\"\n"
                          "[[impulse]]\nat = 1\nbody = \"box\"\nimpulse = [1, 0, 0]\n",
                          "scene.toml:5: impulse[0].body: ", "no body named \"box\" (bodies: rb)"));
}

TEST(ScenarioTomlErrors, ImpulseWithBothImpulseAndTarget)
{
    EXPECT_TRUE(failsWith("[[body]]\nname = \"rb\"\n"
                          "[[impulse]]\nat = 1\nbody = \"rb\"\nimpulse = [1, 0, 0]\n"
                          "velocity = [0, 0, 0]\nangular_velocity = [0, 0, 0]\n",
                          "scene.toml:3: impulse[0]: ", "not both"));
}

TEST(ScenarioTomlErrors, ImpulseWithNeitherImpulseNorTarget)
{
    EXPECT_TRUE(failsWith("[[body]]\nname = \"rb\"\n[[impulse]]\nat = 1\nbody = \"rb\"\n",
                          "scene.toml:3: impulse[0]: ",
                          "needs either impulse (with an optional offset) or a target"));
}

TEST(ScenarioTomlErrors, TargetNeedsBothVelocities)
{
    EXPECT_TRUE(failsWith("[[body]]\nname = \"rb\"\n"
                          "[[impulse]]\nat = 1\nbody = \"rb\"\nvelocity = [0, 0, 0]\n",
                          "scene.toml:3: impulse[0].angular_velocity: ",
                          "a target needs both velocity and angular_velocity"));
}

TEST(ScenarioTomlErrors, OffsetWithATarget)
{
    EXPECT_TRUE(failsWith("[[body]]\nname = \"rb\"\n"
                          "[[impulse]]\nat = 1\nbody = \"rb\"\nvelocity = [0, 0, 0]\n"
                          "angular_velocity = [0, 0, 1]\noffset = [0, 1, 0]\n",
                          "scene.toml:8: impulse[0].offset: ", "offset goes with impulse"));
}

TEST(ScenarioTomlErrors, NegativeImpulseTime)
{
    EXPECT_TRUE(failsWith("[[body]]\nname = \"rb\"\n"
                          "[[impulse]]\nat = -0.5\nbody = \"rb\"\nimpulse = [1, 0, 0]\n",
                          "scene.toml:4: impulse[0].at: ", "must be >= 0, got -0.5"));
}

TEST(ScenarioTomlErrors, ImpulseWithoutTime)
{
    EXPECT_TRUE(failsWith("[[body]]\nname = \"rb\"\n"
                          "[[impulse]]\nbody = \"rb\"\nimpulse = [1, 0, 0]\n",
                          "scene.toml:3: impulse[0].at: ", "missing"));
}

TEST(ScenarioTomlErrors, ZeroTimeStep)
{
    EXPECT_TRUE(
        failsWith("[world]\ndt = 0\n[[body]]\n", "scene.toml:2: world.dt: ", "must be > 0, got 0"));
}

TEST(ScenarioTomlErrors, NonFiniteTimeStep)
{
    EXPECT_TRUE(failsWith("[world]\n\ndt = inf\n[[body]]\n",
                          "scene.toml:3: world.dt: ", "must be finite, got inf"));
}

TEST(ScenarioTomlErrors, NegativeDuration)
{
    EXPECT_TRUE(failsWith("[world]\nduration = -1\n[[body]]\n",
                          "scene.toml:2: world.duration: ", "must be > 0, got -1"));
}

TEST(ScenarioTomlErrors, ElasticityAboveOne)
{
    EXPECT_TRUE(failsWith("[[body]]\nelasticity = 1.5\n", "scene.toml:2: body[0].elasticity: ",
                          "must be in [0, 1], got 1.5 (body \"body1\")"));
}

TEST(ScenarioTomlErrors, NegativeFriction)
{
    EXPECT_TRUE(failsWith("[[body]]\nfriction = -0.1\n",
                          "scene.toml:2: body[0].friction: ", "must be >= 0, got -0.1"));
}

TEST(ScenarioTomlErrors, StaticFrictionBelowFriction)
{
    EXPECT_TRUE(
        failsWith("[[body]]\nfriction = 0.5\nstatic_friction = 0.3\n",
                  "scene.toml:3: body[0].static_friction: ", "must be >= friction (0.5), got 0.3"));
}

TEST(ScenarioTomlErrors, BadIntegratorListsTheAllowedValues)
{
    EXPECT_TRUE(failsWith("[world]\nintegrator = \"euler\"\n[[body]]\n",
                          "scene.toml:2: world.integrator: ",
                          "must be one of \"exact\", \"handout\", got \"euler\""));
}

TEST(ScenarioTomlErrors, BadResponseListsTheAllowedValues)
{
    EXPECT_TRUE(
        failsWith("[world]\nresponse = \"impulse\"\n[[body]]\n",
                  "scene.toml:2: world.response: ", "must be one of \"sequential\", \"average\""));
}

TEST(ScenarioTomlErrors, FloatSolverIterations)
{
    EXPECT_TRUE(failsWith("[world]\nsolver_iterations = 2.5\n[[body]]\n",
                          "scene.toml:2: world.solver_iterations: ", "expected an integer"));
}

TEST(ScenarioTomlErrors, ZeroSolverIterations)
{
    EXPECT_TRUE(failsWith("[world]\nsolver_iterations = 0\n[[body]]\n",
                          "scene.toml:2: world.solver_iterations: ", "must be between 1"));
}

TEST(ScenarioTomlErrors, UnknownSolverNamesTheChoices)
{
    EXPECT_TRUE(failsWith("[world]\nsolver = \"sofft\"\n[[body]]\n",
                          "scene.toml:2: world.solver: ", "\"exact\""));
}

TEST(ScenarioTomlErrors, SoftSubstepsOutOfRange)
{
    EXPECT_TRUE(failsWith("[world]\nsoft_substeps = 0\n[[body]]\n",
                          "scene.toml:2: world.soft_substeps: ", "must be between 1 and 64"));
    EXPECT_TRUE(failsWith("[world]\nsoft_substeps = 4.0\n[[body]]\n",
                          "scene.toml:2: world.soft_substeps: ", "expected an integer"));
}

TEST(ScenarioTomlErrors, NonPositiveSoftContactHertz)
{
    EXPECT_TRUE(failsWith("[world]\nsoft_contact_hertz = 0\n[[body]]\n",
                          "scene.toml:2: world.soft_contact_hertz: ", "must be > 0"));
}

TEST(ScenarioTomlErrors, NonPositiveContactTolerance)
{
    EXPECT_TRUE(failsWith("[world]\ncontact_tolerance = 0\n[[body]]\n",
                          "scene.toml:2: world.contact_tolerance: ", "must be > 0"));
}

TEST(ScenarioTomlErrors, SleepMustBeABoolean)
{
    EXPECT_TRUE(failsWith("[world]\nsleep = \"yes\"\n[[body]]\n",
                          "scene.toml:2: world.sleep: ", "expected true or false"));
}

TEST(ScenarioTomlErrors, ErrorCarriesLocationAndKey)
{
    const auto error = parseError("[[body]]\nname = \"rb\"\nmass = -2\n");
    ASSERT_TRUE(error.has_value());
    EXPECT_EQ(error->where().file, "scene.toml");
    EXPECT_EQ(error->where().line, 3);
    EXPECT_EQ(error->key(), "body[0].mass");
}

} // namespace
} // namespace tumble::scenario

namespace {

using tumble::scenario::test_support::failsWith;

// issue 14, item 9: a body that starts inside or below the ground is rejected at load time
TEST(ScenarioTomlErrors, BodyInsideTheGroundIsRejectedWithItsLineAndName)
{
    // a 2 m cube centred 0.5 m above the ground: its lowest face is 0.5 m inside
    EXPECT_TRUE(failsWith("[ground]\nheight = 0\n[[body]]\nname = \"rb\"\nposition = [0, 0.5, 0]\n",
                          "scene.toml:5: body[0].position: ",
                          "0.5 m below the ground (y = 0 m): a body must start on or above the "
                          "ground (body \"rb\")"));
    // raised ground from an override, reported at the body's position line
    const std::vector<std::string> raise{"ground.height=5"};
    EXPECT_TRUE(failsWith("[ground]\n[[body]]\nname = \"rb\"\nposition = [0, 3, 0]\n",
                          "scene.toml:4: body[0].position: ", "(body \"rb\")", raise));
    // no position: the default centre (the origin) puts the default cube half in the ground
    EXPECT_TRUE(failsWith("[ground]\n[[body]]\n", "scene.toml:2: body[0].position: ",
                          "1 m below the ground"));
    // a tilted cube: its lowest corner decides (half diagonal of the face, sqrt(2) m)
    EXPECT_TRUE(failsWith("[ground]\n[[body]]\nposition = [0, 1.2, 0]\n"
                          "orientation = { axis = [0, 0, 1], degrees = 45 }\n",
                          "scene.toml:3: body[0].position: ", "below the ground"));
}

TEST(ScenarioTomlErrors, BodyOnOrAboveTheGroundLoads)
{
    EXPECT_NO_THROW((void)tumble::scenario::parseScenario(
        "[ground]\nheight = 1\n[[body]]\nposition = [0, 2, 0]\n", "scene.toml"));
    EXPECT_NO_THROW((void)tumble::scenario::parseScenario(
        "[ground]\n[[body]]\nposition = [0, 1.5, 0]\n"
        "orientation = { axis = [0, 0, 1], degrees = 45 }\n",
        "scene.toml"));
    // no ground, nothing to be inside
    EXPECT_NO_THROW((void)tumble::scenario::parseScenario("[[body]]\n", "scene.toml"));
}

TEST(ScenarioTomlErrors, StaticGeometryIsCheckedLikeEveryOtherKey)
{
    // an unknown motion, and what would move a static body
    EXPECT_TRUE(failsWith("[[body]]\nmotion = \"fixed\"\n", "scene.toml:2: body[0].motion: ",
                          "\"dynamic\""));
    EXPECT_TRUE(failsWith("[[body]]\nmotion = \"static\"\nmass = 2\n",
                          "scene.toml:3: body[0].mass: ", "a static body takes no mass"));
    EXPECT_TRUE(failsWith("[[body]]\nmotion = \"static\"\nvelocity = [1, 0, 0]\n",
                          "scene.toml:3: body[0].velocity: ", "a static body takes no velocity"));
    EXPECT_TRUE(failsWith("[[body]]\nmotion = \"static\"\nangular_velocity = [1, 0, 0]\n",
                          "scene.toml:3: body[0].angular_velocity: ", "takes no angular_velocity"));
    // a plane needs a nonzero normal, a point, and known keys
    EXPECT_TRUE(failsWith("[[plane]]\npoint = [0, 0, 0]\nnormal = [0, 0, 0]\n[[body]]\n",
                          "scene.toml:3: plane[0].normal: ", "must be a nonzero vector"));
    EXPECT_TRUE(failsWith("[[plane]]\nnormal = [0, 1, 0]\n[[body]]\n",
                          "scene.toml:1: plane[0].point: ", "missing"));
    EXPECT_TRUE(failsWith("[[plane]]\npoint = [0, 0, 0]\nnormal = [0, 1, 0]\nfrction = 1\n"
                          "[[body]]\n",
                          "scene.toml:4: plane[0].frction: ", ""));
}

TEST(ScenarioTomlErrors, ADynamicBodyMayNotStartInsideAnotherOrInsideAPlane)
{
    // two unit cubes 0.5 m apart centre to centre overlap by 0.5 m
    EXPECT_TRUE(failsWith("[[body]]\nname = \"a\"\nsize = [1, 1, 1]\n[[body]]\nname = \"b\"\n"
                          "size = [1, 1, 1]\nposition = [0.5, 0, 0]\n",
                          "scene.toml:7: body[1].position: ", "overlaps body \"a\" by 0.5 m"));
    // touching is allowed, and static bodies may overlap each other
    EXPECT_NO_THROW((void)tumble::scenario::parseScenario(
        "[[body]]\nsize = [1, 1, 1]\n[[body]]\nsize = [1, 1, 1]\nposition = [1, 0, 0]\n",
        "scene.toml"));
    EXPECT_NO_THROW((void)tumble::scenario::parseScenario(
        "[[body]]\nmotion = \"static\"\n[[body]]\nmotion = \"static\"\nposition = [1, 0, 0]\n"
        "[[body]]\nposition = [0, 5, 0]\n",
        "scene.toml"));
    // a cube whose centre is 0.25 m from a plane of normal +x sinks 0.75 m into it
    EXPECT_TRUE(failsWith("[[plane]]\npoint = [0, 0, 0]\nnormal = [2, 0, 0]\n[[body]]\n"
                          "position = [0.25, 0, 0]\n",
                          "scene.toml:5: body[0].position: ", "0.75 m inside plane[0]"));
}

} // namespace
