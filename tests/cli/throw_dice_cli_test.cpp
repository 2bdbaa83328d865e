// End-to-end tests of `tumble throw` on scenarios of several dice: the report, the summary JSON's
// exact shape, byte-identical summaries whatever the thread count or number of MPI ranks, replay
// files, bad [throw] keys; and the single-die files, whose outputs must not change at all.
#include "cli_support.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <regex>
#include <string>

namespace {

using namespace tumble::cli_test;

const std::string kTray = (kScenarioDir / "dice_two_in_tray.toml").string();
const std::string kDiceCube = (kScenarioDir / "dice_cube.toml").string();

/// FNV-1a, 64 bits: a fingerprint of a file too long to keep in a test.
std::uint64_t fnv1a(const std::string& text)
{
    std::uint64_t hash = 0xcbf29ce484222325ULL;
    for (const char c : text) {
        hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
    }
    return hash;
}

TEST_F(CliTest, ThrowDiceReportsFacesJointTableSumCockedAndUnsettled)
{
    const Result result = runTumble({"throw", kTray, "--throws", "40", "--threads", "2"},
                                    Capture::StdoutOnly);
    ASSERT_EQ(result.exitCode, 0) << result.output;
    for (const char* expected :
         {"die d1: face", "die d2: face", "joint table (face down): rows d1, columns d2",
          "chi-square test of independence", "sum of the faces up",
          "chi-square test against the fair sum", "unsettled (not at rest by max_time = 10 s)",
          "cocked dice (no face within 5 degrees"}) {
        EXPECT_NE(result.output.find(expected), std::string::npos) << expected << '\n'
                                                                   << result.output;
    }
}

TEST_F(CliTest, ThrowDiceSummaryJsonHasTheDocumentedShapeAndIgnoresThreads)
{
    const fs::path json1 = dir() / "one.json";
    const fs::path json2 = dir() / "two.json";
    const fs::path csv1 = dir() / "one.csv";
    const fs::path csv2 = dir() / "two.csv";
    ASSERT_EQ(runTumble({"throw", kTray, "--throws", "48", "--seed", "4", "--threads", "1",
                         "--summary-json", json1.string(), "--csv", csv1.string()})
                  .exitCode,
              0);
    ASSERT_EQ(runTumble({"throw", kTray, "--throws", "48", "--seed", "4", "--threads", "2",
                         "--summary-json", json2.string(), "--csv", csv2.string()})
                  .exitCode,
              0);
    const std::string summary = readFile(json1);
    const std::string faces = R"(\{"\+x": \d+, "-x": \d+, "\+y": \d+, "-y": \d+, "\+z": \d+, "-z": \d+\})";
    EXPECT_TRUE(std::regex_match(
        summary, std::regex(R"(\{"throws": 48, "seed": 4, "unsettled": \d+, "cocked": \d+, )"
                            R"("dice": \{"d1": )" + faces + R"(, "d2": )" + faces +
                            R"(\}, "sum": \{"2": \d+, "3": \d+, "4": \d+, "5": \d+, "6": \d+, )"
                            R"("7": \d+, "8": \d+, "9": \d+, "10": \d+, "11": \d+, "12": \d+\}\}\n)")))
        << summary;
    EXPECT_EQ(summary, readFile(json2));
    EXPECT_EQ(readFile(csv1), readFile(csv2));
    const std::vector<std::string> rows = lines(readFile(csv1));
    ASSERT_EQ(rows.size(), 49u);
    EXPECT_EQ(rows[0], "index,sum,d1_face,d1_cocked,d1_rest_time,d2_face,d2_cocked,d2_rest_time");
}

#ifdef TUMBLE_MPIEXEC
TEST_F(CliTest, ThrowDiceUnderMpirunGivesTheSameSummaryAndCsvAsOneProcess)
{
    const fs::path single = dir() / "single.json";
    const fs::path ranks = dir() / "ranks.json";
    ASSERT_EQ(runTumble({"throw", kTray, "--throws", "37", "--seed", "6", "--threads", "2",
                         "--summary-json", single.string(), "--csv",
                         (dir() / "single.csv").string()})
                  .exitCode,
              0);
    const std::string command = std::string("'") + TUMBLE_MPIEXEC +
                                "' -n 2 --oversubscribe --allow-run-as-root '" + TUMBLE_EXE +
                                "' throw '" + kTray + "' --throws 37 --seed 6 --threads 1 " +
                                "--summary-json '" + ranks.string() + "' --csv '" +
                                (dir() / "ranks.csv").string() + "' 2>&1";
    std::FILE* pipe = popen(command.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string output;
    std::array<char, 4096> buffer{};
    for (std::size_t n = 0; (n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;) {
        output.append(buffer.data(), n);
    }
    const int status = pclose(pipe);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << output;
    EXPECT_NE(output.find("MPI ranks = 2"), std::string::npos) << output;
    EXPECT_EQ(output.find("joint table"), output.rfind("joint table")) << output;
    EXPECT_EQ(readFile(ranks), readFile(single));
    EXPECT_EQ(readFile(dir() / "ranks.csv"), readFile(dir() / "single.csv"));
}
#endif

TEST_F(CliTest, ThrowDiceReplayWritesEveryDieAndRunsAsAScenario)
{
    const fs::path out = dir() / "throw2.toml";
    const Result replay =
        runTumble({"throw", kTray, "--seed", "3", "--replay", "2", "--out", out.string()});
    ASSERT_EQ(replay.exitCode, 0) << replay.output;
    EXPECT_NE(replay.output.find("die d1: "), std::string::npos) << replay.output;
    EXPECT_NE(replay.output.find("die d2: "), std::string::npos) << replay.output;
    const std::string text = readFile(out);
    EXPECT_EQ(text.find("[throw]"), std::string::npos);
    EXPECT_NE(text.find("name = \"wall_west\"\nmotion = \"static\""), std::string::npos) << text;
    const Result run = runTumble({"run", out.string()}, Capture::StdoutOnly);
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("d1 came to rest"), std::string::npos) << run.output;
}

TEST_F(CliTest, ThrowDiceBadKeysExitWithTwoNamingFileLineAndKey)
{
    const Result result = runTumble({"throw", kTray, "--set", "throw.release=\"sideways\""},
                                    Capture::StderrOnly);
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find("throw.release: must be one of \"each\", \"cluster\""),
              std::string::npos)
        << result.output;
    const Result cramped = runTumble(
        {"throw", kTray, "--set", "throw.region={ min = [0, 0.1, 0], max = [0.001, 0.1, 0] }"},
        Capture::StderrOnly);
    EXPECT_EQ(cramped.exitCode, 2) << cramped.output;
    EXPECT_NE(cramped.output.find("throw.region: die 2 of throw 0 overlaps"), std::string::npos)
        << cramped.output;
}

// The outputs below were captured from `tumble throw scenarios/dice_cube.toml --throws 40
// --seed 2026 --threads 1` built from the commit before several dice were added (4263db4), by
// running that code: a single-die [throw] file must keep them byte for byte.
TEST_F(CliTest, ThrowSingleDieFileKeepsItsSummaryAndCsvByteForByte)
{
    const fs::path json = dir() / "die.json";
    const fs::path csv = dir() / "die.csv";
    ASSERT_EQ(runTumble({"throw", kDiceCube, "--throws", "40", "--seed", "2026", "--threads", "1",
                         "--summary-json", json.string(), "--csv", csv.string()})
                  .exitCode,
              0);
    EXPECT_EQ(readFile(json), "{\"throws\": 40, \"faces\": {\"+x\": 7, \"-x\": 6, \"+y\": 9, \"-y\": 7, "
                              "\"+z\": 6, \"-z\": 5}, \"unsettled\": 0, \"seed\": 2026}\n");
    const std::string rows = readFile(csv);
    EXPECT_EQ(lines(rows).at(1), "0,-z,1.2833333333333332,0,0.67119657075175776,0,1.3636602038766494,"
              "-0.52671368470921509,-0.68549048635345611,-4.4192479299791811,11.114940548647747,"
              "-1.1953023630577846,0.3487192704462328,0.0019548252157911691,-0.78201517740604243,"
              "0.5165687866919747");
    EXPECT_EQ(fnv1a(rows), 0x51d9bc6744234a97ULL) << rows;
}

} // namespace
