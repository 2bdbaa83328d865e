// End-to-end tests of what a new user trips over (issue 14): thread counts, command-line
// messages, printed digits, plots, signals, clashing outputs and the end time of a run.
#include "cli_support.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using namespace tumble::cli_test;

const std::string kFriction = (kScenarioDir / "part3_task4_friction.toml").string();
const std::string kDice = (kScenarioDir / "dice_cube.toml").string();

/// Expects exit code 2 and exactly one line "tumble: error: ..." on stderr containing `needle`.
void expectUsageError(std::initializer_list<std::string> arguments, const std::string& needle)
{
    const Result result = runTumble(arguments, Capture::StderrOnly);
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_EQ(result.output.rfind("tumble: error: ", 0), 0u) << result.output;
    EXPECT_EQ(lines(result.output).size(), 1u) << result.output;
    EXPECT_NE(result.output.find(needle), std::string::npos) << result.output;
}

// item 4: one rule for --threads in every command: 0 = all cores, an upper bound, exit 2 above
TEST(CliThreads, EveryCommandRejectsThreadCountsAboveTheBound)
{
    for (const char* count : {"100000", "50000", "5000", "257", "-1"}) {
        expectUsageError({"run", kFriction, "--quiet", "--threads", count}, "--threads");
        expectUsageError({"throw", kDice, "--throws", "1", "--threads", count}, "--threads");
        expectUsageError({"bench", "--threads", count}, "--threads");
    }
    expectUsageError({"run", kFriction, "--threads", "100000"}, "from 0 (one per core) to 256");
}

TEST(CliThreads, ZeroMeansEveryCoreInEveryCommand)
{
    EXPECT_EQ(runTumble({"run", kFriction, "--quiet", "--duration", "0.1", "--threads", "0"})
                  .exitCode,
              0);
    const Result thrown = runTumble({"throw", kDice, "--throws", "4", "--threads", "0"});
    EXPECT_EQ(thrown.exitCode, 0) << thrown.output;
    EXPECT_NE(thrown.output.find("threads = "), std::string::npos) << thrown.output;
    EXPECT_EQ(runTumble({"throw", kDice, "--throws", "4", "--threads", "256"}).exitCode, 0);
}

// item 16: range messages are one line with the prefix and plain numbers
TEST(CliMessages, RangeErrorsAreOneLineWithPlainNumbers)
{
    expectUsageError({"validate", "--dt", "0"}, "--dt: must be a number above 0, got '0'");
    expectUsageError({"throw", kDice, "--throws", "abc"}, "--throws: must be a whole number");
    expectUsageError({"run", kFriction, "--every", "0"}, "--every");
    const Result result = runTumble({"validate", "--dt", "0"}, Capture::StderrOnly);
    EXPECT_EQ(result.output.find("179769313486231570814527423731704356798070567525844996598917"),
              std::string::npos)
        << result.output;
}

// item 17: help, unknown commands and --version follow the one convention
TEST(CliMessages, HelpAndVersionAndUnknownCommands)
{
    const Result help = runTumble({"help"}, Capture::StdoutOnly);
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.output.find("Subcommands:"), std::string::npos) << help.output;
    expectUsageError({"RUN"}, "unknown command 'RUN'");
    expectUsageError({}, "a command is required");
    const Result version = runTumble({"--version"}, Capture::StdoutOnly);
    EXPECT_EQ(version.exitCode, 0);
    EXPECT_EQ(version.output.rfind("tumble ", 0), 0u) << version.output;
}

} // namespace

namespace {

using namespace tumble::cli_test;

// item 5: the console prints the double's digits, not a float's
TEST_F(CliTest, ConsolePrintsTheDoublesOwnDigits)
{
    const std::string file = writeScenario("digits.toml",
                                           "[world]\nduration = 0.01\n"
                                           "[[body]]\nname = \"far\"\n"
                                           "position = [123456.789, 5, 0]\n"
                                           "[[body]]\nname = \"speck\"\nmass = 1e-6\n"
                                           "size = [0.001, 0.001, 0.001]\nposition = [0, 5, 0]\n"
                                           "[[impulse]]\nat = 0.005\nbody = \"speck\"\n"
                                           "impulse = [0, 1e-7, 0]\n");
    const Result result = runTumble({"run", file});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("position = vec3(123456.789000, "), std::string::npos)
        << result.output;
    EXPECT_EQ(result.output.find("123456.789062"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("mat3x3((6e+12, 0, 0), (0, 6e+12, 0), (0, 0, 6e+12))"),
              std::string::npos)
        << result.output;
    EXPECT_EQ(result.output.find("6000000106496"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("impulse = vec3(0, 1e-07, 0) N s"), std::string::npos)
        << result.output;
    EXPECT_EQ(result.output.find("-0.000000"), std::string::npos) << result.output;
}

} // namespace
