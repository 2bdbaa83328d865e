// Extreme but valid parameters (extreme_cases.hpp): no NaN, no tunnelling, no energy gain, no
// penetration, for every case of the table docs/robustness.md is generated from.
#include "extreme_cases.hpp"

#include <gtest/gtest.h>

#include <ostream>
#include <string>

namespace tumble::robustness {

/// GoogleTest names a failing case by this instead of dumping its bytes.
inline void PrintTo(const ExtremeCase& value, std::ostream* out) { *out << value.name; }

namespace {

class Extreme : public ::testing::TestWithParam<ExtremeCase> {};

TEST_P(Extreme, StaysFiniteBoundedAndOutOfTheGround)
{
    const ExtremeCase& extreme = GetParam();
    const DropOutcome outcome = runDrop(extreme.drop);
    EXPECT_TRUE(outcome.finite) << "non-finite after step " << outcome.steps;
    EXPECT_EQ(outcome.steps, extreme.drop.steps);
    EXPECT_TRUE(outcome.energyBounded())
        << "energy rose by " << outcome.maxRelativeEnergyGain << " of the energy scale";
    EXPECT_TRUE(outcome.penetrationBounded()) << "penetration " << outcome.maxPenetration << " m";
    EXPECT_TRUE(outcome.quaternionUnit()) << "| |q| - 1 | = " << outcome.maxQuaternionError;
    EXPECT_GT(outcome.impacts, 0) << "never reached the ground";
    if (extreme.mustBounce) {
        const Real approach = -extreme.drop.velocity.y;
        EXPECT_NEAR(outcome.fastestApproach, approach, 0.01 * approach + 0.2);
        // Up at e times the approach speed, less what gravity took in the rest of that step.
        const Real expected = extreme.drop.restitution * outcome.fastestApproach;
        EXPECT_NEAR(outcome.fastestRebound, expected, 0.01 * expected + 9.81 * extreme.drop.dt);
    }
}

std::string caseName(const ::testing::TestParamInfo<ExtremeCase>& info)
{
    std::string name;
    for (const char c : info.param.name) {
        name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    }
    return name + "_" + std::to_string(info.index);
}

INSTANTIATE_TEST_SUITE_P(Table, Extreme, ::testing::ValuesIn(extremeCases()), caseName);

} // namespace
} // namespace tumble::robustness
