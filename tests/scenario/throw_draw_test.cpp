// Drawing a throw: deterministic in (seed, index) whatever the order, inside the [throw] ranges,
// with a unit orientation.
#include "tumble/scenario/throw.hpp"

#include "tumble/scenario/scenario.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <vector>

namespace tumble::scenario {
namespace {

const std::filesystem::path kDiceCube = std::filesystem::path(TUMBLE_SCENARIO_DIR) / "dice_cube.toml";

/// Bit-for-bit equality of two states (== would call -0 and 0 equal).
bool sameBits(const ThrowState& a, const ThrowState& b)
{
    return std::memcmp(&a, &b, sizeof(ThrowState)) == 0;
}

TEST(ThrowDraw, SameSeedAndIndexGiveTheSameStateInAnyOrder)
{
    const Scenario dice = loadScenario(kDiceCube);
    std::vector<ThrowState> forward;
    for (std::uint64_t i = 0; i < 50; ++i) {
        forward.push_back(drawThrow(dice, 7, i));
    }
    for (std::uint64_t i = 50; i-- > 0;) {
        EXPECT_TRUE(sameBits(drawThrow(dice, 7, i), forward[i])) << "throw " << i;
    }
}

TEST(ThrowDraw, DifferentSeedsAndIndicesGiveDifferentStates)
{
    const Scenario dice = loadScenario(kDiceCube);
    EXPECT_FALSE(sameBits(drawThrow(dice, 7, 3), drawThrow(dice, 7, 4)));
    EXPECT_FALSE(sameBits(drawThrow(dice, 7, 3), drawThrow(dice, 8, 3)));
    // (seed, index) and (index, seed) are different streams
    EXPECT_FALSE(sameBits(drawThrow(dice, 3, 7), drawThrow(dice, 7, 3)));
    EXPECT_NE(throwSeed(0, 1), throwSeed(1, 0));
}

TEST(ThrowDraw, DrawsLieInTheRangesWithAUnitOrientation)
{
    const Scenario dice = loadScenario(
        kDiceCube, std::vector<std::string>{"throw.height=[0.3, 0.4]", "throw.speed=[1, 1.5]",
                                            "throw.vertical_speed=[-2, -1]",
                                            "throw.angular_speed=[10, 12]", "ground.height=0.5"});
    constexpr Real kRounding = 1e-12;
    for (std::uint64_t i = 0; i < 2000; ++i) {
        const ThrowState state = drawThrow(dice, 99, i);
        SCOPED_TRACE(i);
        EXPECT_EQ(state.position.x, 0.0);
        EXPECT_EQ(state.position.z, 0.0);
        EXPECT_GE(state.position.y - 0.5, 0.3 - kRounding);
        EXPECT_LE(state.position.y - 0.5, 0.4 + kRounding);
        const Real horizontal = std::hypot(state.velocity.x, state.velocity.z);
        EXPECT_GE(horizontal, 1.0 - kRounding);
        EXPECT_LE(horizontal, 1.5 + kRounding);
        EXPECT_GE(state.velocity.y, -2.0);
        EXPECT_LE(state.velocity.y, -1.0);
        const Real spin = glm::length(state.angularVelocity);
        EXPECT_GE(spin, 10.0 - kRounding);
        EXPECT_LE(spin, 12.0 + kRounding);
        EXPECT_NEAR(glm::length(state.orientation), 1.0, 1e-15);
    }
}

TEST(ThrowDraw, RandomOrientationsAndAxesCoverTheSphereEvenly)
{
    // the body's +y axis after a uniform rotation, and the spin axis, are uniform on the sphere:
    // each coordinate has mean 0 and mean square 1/3 (standard error about 0.01 for 2000 draws)
    const Scenario dice = loadScenario(kDiceCube);
    constexpr int kDraws = 2000;
    Vec3 upMean(0.0);
    Vec3 upSquare(0.0);
    Vec3 axisSquare(0.0);
    for (int i = 0; i < kDraws; ++i) {
        const ThrowState state = drawThrow(dice, 5, static_cast<std::uint64_t>(i));
        const Vec3 up = state.orientation * Vec3(0.0, 1.0, 0.0);
        const Vec3 axis = state.angularVelocity / glm::length(state.angularVelocity);
        upMean += up / Real{kDraws};
        upSquare += up * up / Real{kDraws};
        axisSquare += axis * axis / Real{kDraws};
    }
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(upMean[k], 0.0, 0.05);
        EXPECT_NEAR(upSquare[k], 1.0 / 3.0, 0.04);
        EXPECT_NEAR(axisSquare[k], 1.0 / 3.0, 0.04);
    }
}

TEST(ThrowDraw, BodyOrientationKeepsTheFilesOrientationAndTheOtherDraws)
{
    const Scenario random = loadScenario(kDiceCube);
    const Scenario fixed =
        loadScenario(kDiceCube, std::vector<std::string>{"throw.orientation=body"});
    const ThrowState a = drawThrow(random, 11, 2);
    const ThrowState b = drawThrow(fixed, 11, 2);
    EXPECT_EQ(b.orientation, fixed.bodies.front().def.orientation);
    EXPECT_NE(a.orientation, b.orientation);
    EXPECT_EQ(a.velocity, b.velocity);
    EXPECT_EQ(a.angularVelocity, b.angularVelocity);
    EXPECT_EQ(a.position, b.position);
}

TEST(ThrowDraw, NeedsAThrowTable)
{
    const Scenario plain = loadScenario(std::filesystem::path(TUMBLE_SCENARIO_DIR) /
                                        "face_down_drop.toml");
    EXPECT_THROW((void)drawThrow(plain, 1, 0), std::invalid_argument);
}

} // namespace
} // namespace tumble::scenario
