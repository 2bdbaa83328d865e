#include "viewer/sim_runner.hpp"

#include "viewer/scene_bounds.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace tumble::viewer {
namespace {

const std::filesystem::path kScenarios = TUMBLE_SCENARIO_DIR;

TEST(SimRunner, StepsAtTheScenariosDtWhateverTheFrameRate)
{
    SimRunner sim(kScenarios / "face_down_drop.toml");
    const Real dt = sim.scenario().dt;
    int steps = 0;
    for (int frame = 0; frame < 30; ++frame) {
        steps += sim.advance(1.0 / 30.0);
    }
    EXPECT_EQ(steps, 240);
    EXPECT_NEAR(sim.time(), 240 * dt, 1e-12);
}

TEST(SimRunner, PausedTakesNoStepsAndStepOnceTakesOne)
{
    SimRunner sim(kScenarios / "face_down_drop.toml");
    sim.setPaused(true);
    EXPECT_EQ(sim.advance(1.0), 0);
    sim.stepOnce();
    EXPECT_EQ(sim.runner().stepCount(), 1);
    EXPECT_TRUE(sim.paused());
}

TEST(SimRunner, TimeScaleIsClamped)
{
    SimRunner sim(kScenarios / "face_down_drop.toml");
    sim.setTimeScale(0.01);
    EXPECT_EQ(sim.timeScale(), SimRunner::kMinTimeScale);
    sim.setTimeScale(10.0);
    EXPECT_EQ(sim.timeScale(), SimRunner::kMaxTimeScale);
    sim.setTimeScale(0.5);
    EXPECT_EQ(sim.advance(1.0 / 60.0) + sim.advance(1.0 / 60.0), 4);
}

TEST(SimRunner, AdvanceToMatchesTumbleRunsStepCount)
{
    SimRunner sim(kScenarios / "part3_task4_friction.toml");
    sim.advanceTo(10.0);
    EXPECT_EQ(sim.runner().stepCount(), 2400);
}

TEST(SimRunner, ResetStartsOverAndKeepsEdits)
{
    SimRunner sim(kScenarios / "face_down_drop.toml");
    int resets = 0;
    sim.setResetListener([&](const scenario::Runner&) { ++resets; });
    EXPECT_EQ(resets, 1);
    sim.setMass(0, 4.0);
    sim.setGravity(Vec3(0.0, -1.0, 0.0));
    sim.advanceTo(0.5);
    sim.reset();
    EXPECT_EQ(resets, 2);
    EXPECT_EQ(sim.time(), 0.0);
    EXPECT_EQ(sim.body(0).mass, 4.0);
    EXPECT_EQ(sim.world().settings().gravity, Vec3(0.0, -1.0, 0.0));
}

TEST(SimRunner, EditsActOnTheRunningWorld)
{
    SimRunner sim(kScenarios / "part3_task4_friction.toml");
    sim.setSize(0, Vec3(2.0, 2.0, 2.0));
    // the inverse inertia follows the new size: a 2 x 2 x 2 cube of mass 2 has 6 / (m (2^2+2^2))
    EXPECT_NEAR(sim.body(0).invInertiaBody.x, 12.0 / (2.0 * 8.0), 1e-12);
    Material material = sim.scenario().bodies[0].def.material;
    material.restitution = 0.9;
    sim.setMaterial(0, material);
    EXPECT_EQ(sim.body(0).material.restitution, 0.9);
    sim.setDt(0.001);
    EXPECT_NEAR(sim.runner().scenario().dt, 1.0 / 240.0, 1e-15);
    sim.reset();
    EXPECT_EQ(sim.runner().scenario().dt, 0.001);
}

TEST(SimRunner, ReloadReadsTheFileAgainAndOpenSwitchesScenario)
{
    // one file per process: ctest runs tests side by side, and build trees may share /tmp
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() /
        ("tumble_viewer_reload_" + std::to_string(getpid()) + ".toml");
    const auto write = [&](double height) {
        std::ofstream out(file);
        out << "[ground]\n[[body]]\nposition = [0, " << height << ", 0]\n";
    };
    write(3.0);
    SimRunner sim(file);
    EXPECT_EQ(sim.body(0).position.y, 3.0);
    write(7.0);
    EXPECT_TRUE(sim.reload());
    EXPECT_EQ(sim.body(0).position.y, 7.0);

    // a broken file keeps the scenario running and says why
    {
        std::ofstream out(file);
        out << "[[body]]\nmass = -1\n";
    }
    EXPECT_FALSE(sim.reload());
    EXPECT_FALSE(sim.error().empty());
    EXPECT_EQ(sim.body(0).position.y, 7.0);

    const int serial = sim.scenarioSerial();
    EXPECT_TRUE(sim.open(kScenarios / "part3_task4_friction.toml"));
    EXPECT_EQ(sim.scenarioSerial(), serial + 1);
    EXPECT_EQ(sim.runner().bodyName(0), "rb");
    std::filesystem::remove(file);
}

TEST(SimRunner, ListenersSeeEveryStepAndTheCollisions)
{
    SimRunner sim(kScenarios / "face_down_drop.toml");
    int steps = 0;
    int collisions = 0;
    sim.setStepListener([&](const scenario::Runner&, const scenario::StepReport& report) {
        ++steps;
        collisions += static_cast<int>(report.collisions.size());
    });
    sim.advanceTo(1.0);
    EXPECT_EQ(steps, 240);
    // dropped 2 m: it lands at 0.64 s
    EXPECT_GE(collisions, 1);
    ASSERT_TRUE(sim.lastCollisions()[0].has_value());
    EXPECT_NEAR(sim.lastCollisions()[0]->time, 0.6386, 0.01);
}

TEST(SimRunner, ImpulsesFromTheViewerAreReportedAndTargetsSolved)
{
    SimRunner sim(kScenarios / "part3_task1_impulse.toml");
    std::vector<scenario::AppliedImpulse> applied;
    sim.setStepListener([&](const scenario::Runner&, const scenario::StepReport& report) {
        applied.insert(applied.end(), report.impulses.begin(), report.impulses.end());
    });
    // the handout's answer: J = (-4, 0, 0) one metre below the centre of mass
    const ImpulseTarget solved =
        sim.applyTarget(0, Vec3(0.0), Vec3(0.0, 0.0, -0.6), "part 3 task 1");
    ASSERT_EQ(solved.status, ImpulseTargetStatus::Reached);
    EXPECT_NEAR(solved.impulse.x, -4.0, 1e-9);
    EXPECT_NEAR(solved.offset.y, -1.0, 1e-9);
    EXPECT_NEAR(sim.body(0).angularVelocity.z, -0.6, 1e-9);
    ASSERT_EQ(applied.size(), 1u);
    EXPECT_TRUE(applied[0].solvedFromTarget);

    // spinning without moving needs no single impulse
    const ImpulseTarget spin = sim.applyTarget(0, sim.body(0).linearVelocity,
                                               Vec3(0.0, 0.0, 1.0), "spin only");
    EXPECT_EQ(spin.status, ImpulseTargetStatus::SpinWithoutImpulse);
    EXPECT_FALSE(sim.error().empty());
    EXPECT_EQ(applied.size(), 1u);

    sim.applyImpulse(0, Vec3(2.0, 0.0, 0.0), Vec3(0.0), "push");
    EXPECT_NEAR(sim.body(0).linearVelocity.x, 1.0, 1e-9);
    EXPECT_EQ(applied.size(), 2u);
}

TEST(SceneBounds, HoldTheBodiesAndTheGroundUnderThem)
{
    SimRunner sim(kScenarios / "part3_task4_friction.toml");
    const ViewBounds bounds = sceneBounds(sim.scenario());
    // the 2 x 6 x 2 block starts 5 m up: its sphere reaches 5 + sqrt(11) m
    EXPECT_GE(bounds.centre.y + bounds.radius, 5.0f + std::sqrt(11.0f) - 1e-4f);
    EXPECT_LE(bounds.centre.y - bounds.radius, 0.0f);
    EXPECT_LT(referenceGridHeight(sim.scenario()), 5.0f - std::sqrt(11.0f));
}

TEST(RunBounds, HoldWhereTheBodiesGo)
{
    // the part 3 task 1 block moves at 2 m/s for 2 s, then stops: it ends 4 m along x
    SimRunner sim(kScenarios / "part3_task1_impulse.toml");
    const ViewBounds start = sceneBounds(sim.scenario());
    const ViewBounds run = runBounds(sim.scenario());
    const float radius = std::sqrt(11.0f);
    EXPECT_GE(run.centre.x + run.radius, 4.0f + radius - 1e-3f);
    EXPECT_LE(run.centre.x - run.radius, -radius + 1e-3f);
    EXPECT_GT(run.radius, start.radius + 1.5f);
}

} // namespace
} // namespace tumble::viewer
