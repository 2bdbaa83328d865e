// Every bad input of bad_inputs.hpp is rejected with a one-line ScenarioError naming the problem,
// never a crash, a hang or a silently clamped value.
#include "bad_inputs.hpp"

#include "tumble/scenario/scenario.hpp"

#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

namespace tumble::robustness {

/// GoogleTest names a failing case by this instead of dumping its bytes.
inline void PrintTo(const BadInput& value, std::ostream* out) { *out << value.kind; }

namespace {

class BadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputTest, IsRejectedWithAOneLineMessage)
{
    const BadInput& input = GetParam();
    std::vector<std::string> overrides;
    if (!input.override.empty()) {
        overrides.emplace_back(input.override);
    }
    try {
        const scenario::Scenario loaded = scenario::parseScenario(input.text, "bad.toml", overrides);
        FAIL() << "accepted: " << input.kind;
    } catch (const scenario::ScenarioError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(input.expected), std::string::npos)
            << "message: " << message << "\nexpected to contain: " << input.expected;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

std::string kindName(const ::testing::TestParamInfo<BadInput>& info)
{
    std::string name;
    for (const char c : info.param.kind) {
        name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    }
    return name;
}

INSTANTIATE_TEST_SUITE_P(Table, BadInputTest, ::testing::ValuesIn(badInputs()), kindName);

} // namespace
} // namespace tumble::robustness
