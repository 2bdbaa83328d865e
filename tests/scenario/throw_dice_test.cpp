// Throws of several dice: independent, deterministic draws that start clear of each other and of
// static geometry; a replay file that reproduces every die's face and rest time bit for bit; faces
// read against the support, and cocked dice.
#include "tumble/scenario/scenario.hpp"
#include "tumble/scenario/throw.hpp"
#include "tumble/scenario/throw_dice.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <numbers>

namespace tumble::scenario {
namespace {

const std::filesystem::path kScenarios = TUMBLE_SCENARIO_DIR;

Scenario tray() { return loadScenario(kScenarios / "dice_two_in_tray.toml"); }

Transform poseOf(const ThrowState& state)
{
    return {state.position, normalizedOrientation(state.orientation)};
}

TEST(DrawDice, EachDieHasItsOwnStreamAndTheDrawIsRepeatable)
{
    const Scenario scenario = tray();
    const std::vector<ThrowState> first = drawDice(scenario, 7, 3);
    const std::vector<ThrowState> again = drawDice(scenario, 7, 3);
    ASSERT_EQ(first.size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_EQ(first[k].position, again[k].position);
        EXPECT_EQ(first[k].velocity, again[k].velocity);
        EXPECT_EQ(first[k].orientation, again[k].orientation);
    }
    EXPECT_NE(first[0].position, first[1].position);
    EXPECT_NE(first[0].angularVelocity, first[1].angularVelocity);
    EXPECT_NE(drawDice(scenario, 7, 4)[0].position, first[0].position);
    EXPECT_NE(drawDice(scenario, 8, 3)[0].position, first[0].position);
    EXPECT_EQ(dieSeed(7, 3, 0), throwSeed(7, 3));
    EXPECT_NE(dieSeed(7, 3, 1), dieSeed(7, 3, 0));
}

TEST(DrawDice, DiceStartInTheRegionClearOfEachOtherAndTheTray)
{
    const Scenario scenario = tray();
    const ThrowRegion& region = *scenario.throwSpec->region;
    const std::vector<std::size_t> dice = diceOf(scenario);
    for (std::uint64_t index = 0; index < 200; ++index) {
        std::vector<bool> placed;
        const std::vector<ThrowState> states = drawDice(scenario, 1, index, &placed);
        const Vec3 half = scenario.bodies[dice[0]].def.shape.halfExtents();
        for (std::size_t k = 0; k < states.size(); ++k) {
            EXPECT_TRUE(placed[k]);
            for (int axis = 0; axis < 3; ++axis) {
                EXPECT_GE(states[k].position[axis], region.min[axis]);
                EXPECT_LE(states[k].position[axis], region.max[axis]);
            }
            for (const BodySpec& body : scenario.bodies) {
                if (body.def.motion == BodyMotion::Static) {
                    EXPECT_LE(cuboidOverlapDepth(poseOf(states[k]), half,
                                                 {body.def.position, body.def.orientation},
                                                 body.def.shape.halfExtents()),
                              0.0);
                }
            }
        }
        EXPECT_LE(cuboidOverlapDepth(poseOf(states[0]), half, poseOf(states[1]), half), 0.0)
            << "throw " << index;
    }
}

TEST(DrawDice, ACrampedRegionRedrawsAndThenGivesUp)
{
    // two dice in a region the size of one: the second can never fit
    Scenario scenario = tray();
    scenario.throwSpec->region = ThrowRegion{Vec3(0.0, 0.1, 0.0), Vec3(0.0, 0.1, 0.0)};
    std::vector<bool> placed;
    (void)drawDice(scenario, 1, 0, &placed);
    EXPECT_TRUE(placed[0]);
    EXPECT_FALSE(placed[1]);
    std::vector<DieOutcome> outcomes(2);
    runDiceThrow(scenario, 1, 0, outcomes);
    EXPECT_EQ(outcomes[0].unplaced, 1);
    EXPECT_EQ(outcomes[0].settled, 0);
}

TEST(DrawDice, AClusterSharesTheHandsVelocityWithinItsRadius)
{
    const Scenario scenario = loadScenario(kScenarios / "craps_wall.toml");
    const Real radius = scenario.throwSpec->clusterRadius;
    for (std::uint64_t index = 0; index < 50; ++index) {
        const std::vector<ThrowState> states = drawDice(scenario, 3, index);
        EXPECT_EQ(states[0].velocity, states[1].velocity);
        EXPECT_LE(glm::length(states[0].position - states[1].position), 2.0 * radius);
        // the heading is within 10 degrees of +x
        const Vec3& v = states[0].velocity;
        EXPECT_LE(std::abs(std::atan2(v.z, v.x)), 10.0 * std::numbers::pi / 180.0 + 1e-12);
    }
}

TEST(DrawDice, OneDieDrawsExactlyAsTheSingleDieModel)
{
    const Scenario scenario = loadScenario(kScenarios / "dice_cube.toml");
    for (std::uint64_t index = 0; index < 20; ++index) {
        const ThrowState single = drawThrow(scenario, 11, index);
        const ThrowState die = drawDice(scenario, 11, index).front();
        EXPECT_EQ(single.position, die.position);
        EXPECT_EQ(single.velocity, die.velocity);
        EXPECT_EQ(single.angularVelocity, die.angularVelocity);
        EXPECT_EQ(single.orientation, die.orientation);
    }
}

/// Runs the replay file of throw `index` as `tumble run` builds it, into outcomes.
std::vector<DieOutcome> runReplay(const Scenario& scenario, std::uint64_t seed,
                                  std::uint64_t index)
{
    const std::string text = diceScenarioToml(scenario, drawDice(scenario, seed, index), "replay");
    const Scenario replay = parseScenario(text, "replay.toml");
    EXPECT_FALSE(replay.throwSpec.has_value());
    BuiltWorld built = buildWorld(replay);
    std::vector<BodyId> ids;
    for (const std::size_t body : diceOf(replay)) {
        ids.push_back(built.bodies[body]);
    }
    std::vector<DieOutcome> outcomes(ids.size());
    runDiceWorld(built.world, ids, replay.duration, replay.dt, outcomes);
    return outcomes;
}

/// Whether two numbers have the same bits (so +0 and -0 differ).
bool sameBits(Real a, Real b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(DiceReplay, TheReplayFileHoldsEveryBodyToTheBitSignedZerosIncluded)
{
    // the tower's baffles are turned about one axis: their quaternions hold components -0, which
    // a replay must keep, or the replayed throw rounds differently from the throw
    const Scenario scenario = loadScenario(kScenarios / "dice_tower.toml");
    const std::vector<ThrowState> states = drawDice(scenario, 5, 2);
    const Scenario thrown = diceScenario(scenario, states);
    const Scenario replay = parseScenario(diceScenarioToml(scenario, states, "replay"), "r.toml");
    ASSERT_EQ(thrown.bodies.size(), replay.bodies.size());
    for (std::size_t i = 0; i < thrown.bodies.size(); ++i) {
        const BodyDef& a = thrown.bodies[i].def;
        const BodyDef& b = replay.bodies[i].def;
        for (int k = 0; k < 4; ++k) {
            EXPECT_TRUE(sameBits(a.orientation[k], b.orientation[k])) << "body " << i;
        }
        for (int k = 0; k < 3; ++k) {
            EXPECT_TRUE(sameBits(a.position[k], b.position[k])) << "body " << i;
            EXPECT_TRUE(sameBits(a.linearVelocity[k], b.linearVelocity[k])) << "body " << i;
            EXPECT_TRUE(sameBits(a.angularVelocity[k], b.angularVelocity[k])) << "body " << i;
        }
    }
}

TEST(DiceReplay, ReproducesEveryDiesFaceAndRestTimeExactly)
{
    for (const char* file : {"dice_two_in_tray.toml", "dice_tower.toml", "craps_wall.toml"}) {
        const Scenario scenario = loadScenario(kScenarios / file);
        for (std::uint64_t index = 0; index < 3; ++index) {
            SCOPED_TRACE(std::string(file) + " throw " + std::to_string(index));
            std::vector<DieOutcome> thrown(2);
            runDiceThrow(scenario, 5, index, thrown);
            const std::vector<DieOutcome> replayed = runReplay(scenario, 5, index);
            ASSERT_EQ(replayed.size(), 2u);
            for (std::size_t k = 0; k < 2; ++k) {
                EXPECT_EQ(thrown[k].settled, replayed[k].settled);
                EXPECT_EQ(thrown[k].face, replayed[k].face);
                EXPECT_EQ(thrown[k].cocked, replayed[k].cocked);
                EXPECT_EQ(thrown[k].restTime, replayed[k].restTime);
            }
        }
    }
}

TEST(DiceRun, TwoDiceInTheTrayComeToRestTogether)
{
    const Scenario scenario = tray();
    int settled = 0;
    for (std::uint64_t index = 0; index < 10; ++index) {
        std::vector<DieOutcome> outcomes(2);
        runDiceThrow(scenario, 1, index, outcomes);
        settled += outcomes[0].settled;
        EXPECT_EQ(outcomes[0].settled, outcomes[1].settled);
        if (outcomes[0].settled != 0) {
            EXPECT_GT(outcomes[0].restTime, 0.0);
            EXPECT_LE(outcomes[0].restTime, scenario.throwSpec->maxTime);
        }
    }
    EXPECT_GE(settled, 9);
}

/// A die of edge 2 cm of 8 g at `position`, turned by `orientation`.
BodyId placeDie(World& world, const Vec3& position, const Quat& orientation)
{
    BodyDef def;
    def.shape.size = Vec3(0.02);
    def.mass = 0.008;
    def.position = position;
    def.orientation = orientation;
    return world.createBody(def);
}

TEST(DieAtRest, AFaceTiltedMoreThanFiveDegreesFromTheFloorIsCocked)
{
    World world;
    world.setGround(Plane{0.0});
    const Real tilt = 20.0 * std::numbers::pi / 180.0;
    const Quat turned = glm::angleAxis(tilt, Vec3(0.0, 0.0, 1.0));
    // the lowest corner on the ground: half the projected extent below the centre
    const Real drop = 0.01 * (std::cos(tilt) + std::sin(tilt));
    const DieOutcome cocked = readDieAtRest(world, placeDie(world, Vec3(0.0, drop, 0.0), turned));
    EXPECT_EQ(cocked.cocked, 1);
    const Quat slight = glm::angleAxis(3.0 * std::numbers::pi / 180.0, Vec3(0.0, 0.0, 1.0));
    const Real low = 0.01 * (std::cos(0.0523599) + std::sin(0.0523599));
    const DieOutcome flat = readDieAtRest(world, placeDie(world, Vec3(0.5, low, 0.0), slight));
    EXPECT_EQ(flat.cocked, 0);
    EXPECT_EQ(static_cast<CuboidFace>(flat.face), CuboidFace::MinusY);
}

TEST(DieAtRest, OnASlopeTheFaceIsMeasuredAgainstTheSlopesNormal)
{
    // a plane tilted 30 degrees about z through the origin, and a die lying flat on it
    World world;
    const Real tilt = 30.0 * std::numbers::pi / 180.0;
    const Vec3 normal(-std::sin(tilt), std::cos(tilt), 0.0);
    (void)world.addPlane(StaticPlane{Vec3(0.0), normal, {}});
    const Quat onSlope = glm::angleAxis(tilt, Vec3(0.0, 0.0, 1.0));
    const DieOutcome die = readDieAtRest(world, placeDie(world, 0.01 * normal, onSlope));
    EXPECT_EQ(die.cocked, 0);
    EXPECT_EQ(static_cast<CuboidFace>(die.face), CuboidFace::MinusY);
}

TEST(DieAtRest, ADieLyingOnAnotherDieRestsOnItsTopFace)
{
    World world;
    world.setGround(Plane{0.0});
    (void)placeDie(world, Vec3(0.0, 0.01, 0.0), Quat(1.0, 0.0, 0.0, 0.0));
    // turned a quarter about x: its +z face is down, flat on the lower die
    const Quat quarter = glm::angleAxis(0.5 * std::numbers::pi, Vec3(1.0, 0.0, 0.0));
    const DieOutcome top = readDieAtRest(world, placeDie(world, Vec3(0.0, 0.03, 0.0), quarter));
    EXPECT_EQ(top.cocked, 0);
    EXPECT_EQ(static_cast<CuboidFace>(top.face), CuboidFace::PlusZ);
}

} // namespace
} // namespace tumble::scenario
