// Regressions for the library bugs the robustness work found (docs/robustness.md), each the
// smallest case that showed it.
#include "drop_case.hpp"

#include "tumble/scenario/runner.hpp"
#include "tumble/scenario/scenario.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>

namespace tumble::robustness {
namespace {

// The time of impact's turning-rate bound took |Pi| for every body-frame momentum component, so
// for a long thin rod (tiny I about its axis) it was thousands of times too large: the search ran
// out of advances, the vertex sank 9 mm into the ground and the push-out added 1e-3 of the energy.
TEST(Regression, ASpinningTenMetreRodLandsWithoutSinkingOrGainingEnergy)
{
    DropCase drop;
    drop.size = Vec3(0.1, 10.0, 0.1);
    drop.orientation = glm::normalize(Quat(1.0, 0.1, 0.2, 0.05));
    drop.angularVelocity = Vec3(1.0, 2.0, 3.0);
    drop.steps = 480;
    const DropOutcome outcome = runDrop(drop);
    EXPECT_GT(outcome.impacts, 0);
    EXPECT_LT(outcome.maxRelativeEnergyGain, 1e-9);
}

// Shortening a sub-step to the time of impact re-solves the resting contact for the shorter
// sub-step, which changes the motion; the search was not repeated on it, so a box rocking on an
// edge sank up to 1.5e-5 m per step and the push-out added up to 1.4e-4 J (this scenario failed
// the 1e-6 relative energy check of tests/scenario/runner_test.cpp once the bound was tightened).
TEST(Regression, ABoxRockingOnItsEdgesGainsNoEnergy)
{
    scenario::Runner runner(scenario::loadScenario(std::filesystem::path(TUMBLE_SCENARIO_DIR) /
                                                   "part3_task3_spin_e07.toml"));
    const BodyId id = runner.bodies().front();
    const auto energy = [&] {
        const Body& body = runner.world().body(id);
        return body.kineticEnergy() + body.potentialEnergy(runner.world().settings().gravity);
    };
    Real before = energy();
    Real largestGain = 0.0;
    for (int step = 0; step < 2400; ++step) {
        runner.step();
        largestGain = std::max(largestGain, energy() - before);
        before = energy();
    }
    // m g (tau kImpactSpeed / 2): the dip a slowly approaching contact may still make (4.5).
    EXPECT_LT(largestGain, 2.0 * 9.81 * (1.0 / 240.0) * 1e-3 / 2.0);
}

// Found by scenario_loader_fuzzer (tests/fuzz/regressions/scenario_loader/
// subnormal_friction_hang.toml): friction 5.1e-309 made the friction bound subnormal, Newton's
// method overflowed 1/bound into NaN, and the sub-step loop (which ended on tau == remaining)
// never ended with a NaN state.
TEST(Regression, ASubnormalFrictionCoefficientIsNoFrictionNotNaN)
{
    DropCase drop;
    drop.friction = 5.1e-309;
    drop.orientation = glm::normalize(Quat(0.9, 0.3, 0.2, 0.1));
    drop.velocity = Vec3(2.0, -1.0, 0.0);
    drop.steps = 480;
    const DropOutcome outcome = runDrop(drop);
    EXPECT_TRUE(outcome.finite);
    EXPECT_GT(outcome.impacts, 0);
}

// Found by world_step_fuzzer (tests/fuzz/regressions/world_step/handout_stick_zero_substep): a
// light 1000 m stick rocking on the ground with the handout integrator at dt = 0.1 s. The world
// left a vertex just above the impact tolerance to the time of impact, whose pose at s = 0 was
// the start pose rounded by the handout rotation (Gram-Schmidt), 3e-14 m lower 500 m out: it
// returned s = 0, and the zero-length sub-step divided by zero in (5.9), making the state NaN.
TEST(Regression, ALightStickRockingUnderTheHandoutIntegratorStaysFinite)
{
    DropCase drop;
    drop.mass = 1.0000000000000004e-06;
    drop.size = Vec3(999.99999999999795, 0.99999999999999911, 0.99999999999999911);
    drop.orientation = Quat(-0.089233959135939789, -0.24795497615194984, 0.77018987765111113,
                            -0.58082973641350166);
    drop.dt = 0.099999999999999895;
    drop.height = 3.0771719819486979e-06;
    drop.velocity = Vec3(-5.4960415188229102e-05, -0.0014058585582373867, 0.0010498162041319566);
    drop.restitution = 0.0;
    drop.friction = 0.0;
    drop.integrator = Integrator::Handout;
    drop.steps = 299;
    const DropOutcome outcome = runDrop(drop);
    EXPECT_TRUE(outcome.finite) << "non-finite after step " << outcome.steps;
    EXPECT_TRUE(outcome.quaternionUnit());
    EXPECT_TRUE(outcome.penetrationBounded());
}

// Found by world_step_fuzzer (tests/fuzz/regressions/world_step/plate_on_edge_solver_cap): a
// heavy 0.27 x 0.27 x 0.001 m plate standing on an edge with friction 5. Its 1 mm wide patch made
// Gauss-Seidel converge so slowly that 256 sweeps left corners approaching at 1e-5 m/s; they sank
// and the push-out (4.5) added 1.3e-5 of the energy scale in 50 steps. A solve that reaches the
// cap now ends with the exact normal impulses (05-normal-impulse.md, (5.11)).
TEST(Regression, APlateStandingOnItsEdgeGainsNoEnergy)
{
    DropCase drop;
    drop.mass = 4944.4460754618676;
    drop.size = Vec3(0.26620924722636491, 0.26623191587757494, 0.001003993048226372);
    drop.orientation = Quat(0.5, 0.5, 0.5, 0.5);
    drop.dt = 0.010944997993195428;
    drop.height = 3.9381243042291276e-10;
    drop.velocity = Vec3(-0.00057735026919321082, -0.00057735026919337974,
                         -0.00057735026919316973);
    drop.restitution = 0.0;
    drop.friction = 5.0;
    drop.steps = 50;
    const DropOutcome outcome = runDrop(drop);
    EXPECT_TRUE(outcome.finite);
    EXPECT_TRUE(outcome.penetrationBounded());
    EXPECT_LE(outcome.maxRelativeEnergyGain, kEnergyTolerance);
}

// Found by world_step_fuzzer (tests/fuzz/regressions/world_step/*_shrinking_substeps and
// light_box_impact_of_the_longer_solve): light bodies pivoting on a corner at dt near 0.1 s. The
// time of impact searched the motion resting-solved over the whole remaining step, found a second
// corner swung down within 1e-4 s, and the motion re-solved over that short sub-step had no impact
// at all: every sub-step advanced ~1e-4 s, and after the 32nd the rest of the step ran unsearched,
// sank up to 0.16 m and the push-out (4.5) added 1-4 % of the energy scale. Now the sub-step is
// searched back up to the impact (4.3a), and the 32nd sub-step ends the step (4.3b).
void expectBoundedDrop(const DropCase& drop)
{
    const DropOutcome outcome = runDrop(drop);
    EXPECT_TRUE(outcome.finite) << "non-finite after step " << outcome.steps;
    EXPECT_TRUE(outcome.penetrationBounded()) << outcome.maxPenetration << " m";
    EXPECT_TRUE(outcome.energyBounded())
        << outcome.maxRelativeEnergyGain << " of the energy scale, tolerance "
        << outcome.energyTolerance();
}

TEST(Regression, ALightStickPivotingOnACornerGainsNoEnergy)
{
    DropCase drop;
    drop.mass = 1.0000000000000004e-06;
    drop.size = Vec3(0.99999999999309264, 0.99999999999309264, 30.997737772072604);
    drop.orientation = Quat(0.57071970705279418, -0.57684524393466308, 0.13625467275531,
                            0.56829855242106242);
    drop.dt = 0.099999999998848815;
    drop.height = 0.0017422018264335668;
    drop.velocity = Vec3(0.0052817733175699278, -0.0095210002472042709, 0.0024984008909781966);
    drop.angularVelocity =
        Vec3(0.12752774644289969, 0.040333262950819307, -0.030555818202072527);
    drop.restitution = 0.023851810179718935;
    drop.friction = 7.2862694888080082;
    drop.steps = 134;
    expectBoundedDrop(drop);
}

TEST(Regression, ASpinningChipWithFrictionTenGainsNoEnergy)
{
    DropCase drop;
    drop.mass = 1.0000000000000004e-06;
    drop.size = Vec3(0.0010000000000000002, 0.0046979674128912949, 0.0010000000000000002);
    drop.orientation = Quat(0.42858176232565875, -0.69107908531493489, 0.57222138667778999,
                            0.10625467270032235);
    drop.dt = 0.099999999998848815;
    drop.height = 2.4484625040526312e-09;
    drop.velocity =
        Vec3(0.0047163221968758171, -0.00090667010273835845, 0.0015618443156448843);
    drop.angularVelocity = Vec3(-2.6807311783611185, -0.98841888531563005, 2.6904855534670702);
    drop.restitution = 0.62748921866291163;
    drop.friction = 9.9999999999900009;
    drop.steps = 142;
    expectBoundedDrop(drop);
}

TEST(Regression, ALightBoxOnACornerIsNotHeldToTheImpactOfTheLongerSolve)
{
    DropCase drop;
    drop.mass = 3.58910475496205e-06;
    drop.size = Vec3(0.78130666894614764, 0.28737466875514434, 0.60539511532701307);
    drop.orientation = Quat(-0.28242548258935096, -0.37226340297707061, -0.60663274966613645,
                            0.643158232957183);
    drop.dt = 0.09325649005773165;
    drop.height = 2.0789272894558605e-05;
    drop.velocity =
        Vec3(0.0022685974986842591, -0.0015165206068471293, 0.0010302636210331344);
    drop.angularVelocity = Vec3(-0.5529027754821696, 1.0105445535600246, -0.10025236199963315);
    drop.restitution = 0.060209539721058469;
    drop.friction = 2.1451805680229521;
    drop.steps = 75;
    expectBoundedDrop(drop);
}

TEST(Regression, AStepWithANonFiniteStateEnds)
{
    World world;
    world.setGround(Plane{});
    const BodyId id = world.createBody(BodyDef{});
    world.setLinearVelocity(id, Vec3(0.0, std::numeric_limits<Real>::quiet_NaN(), 0.0));
    world.step(1.0 / 240.0);
    EXPECT_FALSE(isFiniteState(world.body(id)));
}

} // namespace
} // namespace tumble::robustness
