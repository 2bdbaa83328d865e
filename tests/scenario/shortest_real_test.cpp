// shortestReal, the fallback of scenario messages where the standard library has no
// floating-point to_chars (the web build): it must write what std::to_chars writes here.
#include "shortest_real.hpp"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

namespace tumble::scenario::detail {
namespace {

std::string standardForm(double value)
{
    std::array<char, 64> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return std::string(buffer.data(), result.ptr);
}

TEST(ShortestReal, MatchesToCharsOnValuesScenarioFilesHold)
{
    for (const double value : {0.0, -0.0, 1.0, -1.0, 0.1, 0.5, 1.0 / 240.0, 9.81, -9.81, 100.0,
                               1e-5, 1.2e-4, 0.00012, 1200000.0, 123456789012.0, 1e16, 1e21,
                               1e22, 5e-324, 1.7976931348623157e308, 2.5, 0.3, 1e100, 3e-7}) {
        EXPECT_EQ(shortestReal(value), standardForm(value)) << value;
    }
}

TEST(ShortestReal, MatchesToCharsOnRandomDoublesOfEveryMagnitude)
{
    // random bit patterns cover every exponent; non-finite patterns are left out (messages
    // write those as nan and inf themselves)
    std::mt19937_64 random(19);
    int compared = 0;
    while (compared < 20000) {
        const double value = std::bit_cast<double>(random());
        if (!std::isfinite(value)) {
            continue;
        }
        ASSERT_EQ(shortestReal(value), standardForm(value)) << std::hexfloat << value;
        ++compared;
    }
}

TEST(ShortestReal, MatchesToCharsOnShortDecimals)
{
    // numbers as people type them: few digits at scales from 1e-9 to 1e9
    std::mt19937_64 random(7);
    std::uniform_int_distribution<int> digits(1, 9999);
    std::uniform_int_distribution<int> scale(-12, 9);
    for (int i = 0; i < 20000; ++i) {
        const double value = digits(random) * std::pow(10.0, scale(random));
        ASSERT_EQ(shortestReal(value), standardForm(value)) << value;
    }
}

} // namespace
} // namespace tumble::scenario::detail
