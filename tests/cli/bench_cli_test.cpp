// `tumble bench` on the contact scenes (issue 16): the pile, the stack and the pyramid, shortened
// to a few steps, each print a row with every column filled by a finite number.
#include "cli_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace tumble::cli_test {
namespace {

/// One row of the contact table, as printed.
struct ContactRow {
    std::string scene;
    std::string engine;
    int bodies = 0;
    long steps = 0;
    double msPerStep = 0.0;
    double nsPerBodyStep = 0.0;
    std::string contactsPerStep;
    long atRest = 0;
    /// "-" where the allocator does not count the heap (a sanitizer's)
    std::string bytesPerBody;
    double sideways = 0.0;
    std::string ratio;
};

/// The rows of the contact table in `output`; a number that does not parse fails the test.
std::vector<ContactRow> contactRows(const std::string& output)
{
    // scen engine bodies threads steps runs ms/step ns/body-step contacts/step at-rest
    // bytes/body sideways [ratio]; an engine name may hold a space ("tumble nosleep"), and
    // tumble's empty ratio leaves the line padded with spaces
    static const std::regex row(R"(^(S5|stack20|pyramid) +(.+?) +(\d+) +(\d+) +(\d+) +(\d+) +)"
                                R"((\S+) +(\S+) +(\S+) +(\d+) +(-?\d+|-) +(\S+)(?: +(\S+))? *$)");
    std::vector<ContactRow> rows;
    std::istringstream lines(output);
    std::string line;
    while (std::getline(lines, line)) {
        std::smatch match;
        if (!std::regex_match(line, match, row)) {
            continue;
        }
        ContactRow parsed{.scene = match[1],
                          .engine = match[2],
                          .bodies = std::stoi(match[3]),
                          .steps = std::stol(match[5]),
                          .msPerStep = std::stod(match[7]),
                          .nsPerBodyStep = std::stod(match[8]),
                          .contactsPerStep = match[9],
                          .atRest = std::stol(match[10]),
                          .bytesPerBody = match[11],
                          .sideways = std::stod(match[12]),
                          .ratio = match[13]};
        rows.push_back(parsed);
    }
    return rows;
}

TEST(CliBench, ContactScenesPrintEveryColumnWithFiniteNumbers)
{
    std::vector<std::string> arguments{"bench", "--scenes", "S5,stack20,pyramid", "--duration",
                                       "0.05", "--threads", "1", "--throws", "0"};
#ifdef TUMBLE_TEST_PEERS
    arguments.push_back("--peers");
#endif
    const Result result = runTumble(arguments);
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("ms/step ns/body-step contacts/step at rest bytes/body "
                                 "sideways m"),
              std::string::npos)
        << result.output;
    // S1 and S4 were not asked for
    EXPECT_EQ(result.output.find("\nS1 "), std::string::npos) << result.output;
    const std::vector<ContactRow> rows = contactRows(result.output);
    std::map<std::string, int> tumbleRows;
    for (const ContactRow& row : rows) {
        SCOPED_TRACE(row.scene + " " + row.engine);
        EXPECT_TRUE(std::isfinite(row.msPerStep) && row.msPerStep > 0.0);
        EXPECT_TRUE(std::isfinite(row.nsPerBodyStep) && row.nsPerBodyStep > 0.0);
        EXPECT_TRUE(std::isfinite(row.sideways) && row.sideways >= 0.0);
        EXPECT_LE(row.atRest, row.bodies);
        if (!row.engine.starts_with("tumble")) {
            // a peer: no contact count, its time over tumble's
            EXPECT_EQ(row.contactsPerStep, "-");
            EXPECT_GT(std::stod(row.ratio), 0.0);
            continue;
        }
        ++tumbleRows[row.scene];
        const double contacts = std::stod(row.contactsPerStep);
        EXPECT_TRUE(std::isfinite(contacts) && contacts >= 0.0);
#ifdef TUMBLE_TEST_SANITIZED
        // ASan's allocator leaves glibc's heap counters at zero: the column says it is not known
        EXPECT_EQ(row.bytesPerBody, "-");
#else
        EXPECT_GT(std::stoll(row.bytesPerBody), 0);
#endif
        // 0.05 s at 1/60 s and at 1/240 s
        EXPECT_EQ(row.steps, row.scene == "S5" ? 12 : 3);
    }
    // the pile once with its own sleeping and once without; the stack and pyramid sleep off;
    // each once more with the soft step
    EXPECT_EQ(tumbleRows["S5"], 3) << result.output;
    EXPECT_EQ(tumbleRows["stack20"], 2) << result.output;
    EXPECT_EQ(tumbleRows["pyramid"], 2) << result.output;
    EXPECT_EQ(std::count_if(rows.begin(), rows.end(),
                            [](const ContactRow& row) { return row.engine == "tumble soft"; }),
              1)
        << result.output;
    for (const ContactRow& row : rows) {
        if (row.scene == "stack20" && row.engine == "tumble nosleep") {
            // twenty cubes touching from the start: nineteen faces and the ground carry weight
            EXPECT_GE(std::stod(row.contactsPerStep), 20.0);
            EXPECT_EQ(row.bodies, 20);
        }
        if (row.scene == "pyramid") {
            EXPECT_EQ(row.bodies, 1240);
        }
    }
}

TEST(CliBench, SetOverridesEveryScenarioTimed)
{
    // the stack's own step is 1/60 s: 0.05 s of it is 3 steps, and 10 at the step --set gives
    const Result result =
        runTumble({"bench", "--scenes", "stack20", "--duration", "0.05", "--threads", "1",
                   "--throws", "0", "--set", "world.dt=0.005"});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("every scenario with --set world.dt=0.005"), std::string::npos)
        << result.output;
    const std::vector<ContactRow> rows = contactRows(result.output);
    ASSERT_FALSE(rows.empty()) << result.output;
    for (const ContactRow& row : rows) {
        EXPECT_EQ(row.steps, 10) << row.engine;
    }
}

#ifdef TUMBLE_TEST_PEERS
TEST(CliBench, EveryPeerIsGivenTheScenesRestitutionThreshold)
{
    // the engines bounce alike only if each is given the file's threshold (S5 says 1 m/s);
    // each settings line names the value in force, MuJoCo's spring-damper contacts have none
    const Result result =
        runTumble({"bench", "--scenes", "stack20", "--duration", "0.05", "--threads", "1",
                   "--throws", "0", "--peers", "--set", "world.restitution_threshold=0.3"});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    std::istringstream lines(result.output);
    int checked = 0;
    for (std::string line; std::getline(lines, line);) {
        if (!line.starts_with("settings of ") || line.starts_with("settings of MuJoCo")) {
            continue;
        }
        EXPECT_NE(line.find(" 0.3 m/s"), std::string::npos) << line;
        ++checked;
    }
    EXPECT_GT(checked, 0) << result.output;
}
#endif

TEST(CliBench, AnUnknownKeyInSetIsNamedInAOneLineError)
{
    const Result result = runTumble({"bench", "--scenes", "stack20", "--duration", "0.05",
                                     "--throws", "0", "--set", "world.sweeps=10"});
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find("world.sweeps"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("ms/step"), std::string::npos) << result.output;
}

TEST(CliBench, AnUnknownSceneIsAUsageError)
{
    const Result result = runTumble({"bench", "--scenes", "S9"});
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find("--scenes"), std::string::npos) << result.output;
}

} // namespace
} // namespace tumble::cli_test
