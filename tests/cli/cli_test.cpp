// End-to-end tests of the tumble program: exit codes, error messages, console and CSV output.
#include "cli_support.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <sstream>
#include <utility>
#include <string>
#include <vector>

namespace {

using namespace tumble::cli_test;

/// A small valid scene; line numbers matter to the bad-input tests that change one line.
const std::vector<std::string> kGoodLines = {
    "[world]",                  // 1
    "dt = 0.01",                // 2
    "duration = 0.5",           // 3
    "",                         // 4
    "[ground]",                 // 5
    "height = 0.0",             // 6
    "",                         // 7
    "[[body]]",                 // 8
    "name = \"rb\"",            // 9
    "size = [2, 6, 2]",         // 10
    "mass = 2.0",               // 11
    "position = [0, 5, 0]",     // 12
    "orientation = [1, 0, 0, 0]", // 13
};

/// The good scene with line `number` (1-based) replaced, and `extra` lines appended.
std::string sceneWith(int number, const std::string& replacement,
                      const std::vector<std::string>& extra = {})
{
    std::string text;
    for (std::size_t i = 0; i < kGoodLines.size(); ++i) {
        text += (static_cast<int>(i) + 1 == number ? replacement : kGoodLines[i]) + "\n";
    }
    for (const std::string& line : extra) {
        text += line + "\n";
    }
    return text;
}

/// Expects exit code 2 and one "tumble: error: FILE:LINE: ..." message on stderr naming `key`.
void expectBadInput(const std::string& file, int line, const std::string& key)
{
    const Result result = runTumble({"run", file}, Capture::StderrOnly);
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find("tumble: error: "), std::string::npos) << result.output;
    EXPECT_NE(result.output.find(file + ":" + std::to_string(line) + ":"), std::string::npos)
        << "expected " << file << ":" << line << ": in: " << result.output;
    EXPECT_NE(result.output.find(key), std::string::npos)
        << "expected key " << key << " in: " << result.output;
    EXPECT_EQ(lines(result.output).size(), 1u) << result.output;

    // check reports the same problem the same way
    const Result checked = runTumble({"check", file}, Capture::StderrOnly);
    EXPECT_EQ(checked.exitCode, 2) << checked.output;
    EXPECT_EQ(checked.output, result.output);
}

TEST_F(CliTest, GoodSceneRuns)
{
    const Result result = runTumble({"run", writeScenario("good.toml", sceneWith(0, ""))});
    EXPECT_EQ(result.exitCode, 0) << result.output;
}

TEST_F(CliTest, MissingFileIsBadInput)
{
    const std::string file = (dir() / "does_not_exist.toml").string();
    const Result result = runTumble({"run", file}, Capture::StderrOnly);
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find("tumble: error: " + file), std::string::npos) << result.output;
    EXPECT_EQ(runTumble({"check", file}).exitCode, 2);
}

TEST_F(CliTest, TomlSyntaxErrorIsBadInput)
{
    expectBadInput(writeScenario("syntax.toml", sceneWith(11, "mass = = 2.0")), 11, "");
}

TEST_F(CliTest, UnknownKeyIsBadInput)
{
    expectBadInput(writeScenario("unknown.toml", sceneWith(11, "colour = \"red\"")), 11, "colour");
}

TEST_F(CliTest, WrongTypeIsBadInput)
{
    expectBadInput(writeScenario("type.toml", sceneWith(11, "mass = \"heavy\"")), 11, "mass");
}

TEST_F(CliTest, NonPositiveMassIsBadInput)
{
    expectBadInput(writeScenario("mass.toml", sceneWith(11, "mass = -1.0")), 11, "mass");
    expectBadInput(writeScenario("mass0.toml", sceneWith(11, "mass = 0.0")), 11, "mass");
}

TEST_F(CliTest, ZeroSizeIsBadInput)
{
    expectBadInput(writeScenario("size.toml", sceneWith(10, "size = [2, 0, 2]")), 10, "size");
}

TEST_F(CliTest, NanValueIsBadInput)
{
    expectBadInput(writeScenario("nan.toml", sceneWith(12, "position = [0, nan, 0]")), 12,
                   "position");
}

TEST_F(CliTest, InfiniteValueIsBadInput)
{
    expectBadInput(writeScenario("inf.toml", sceneWith(12, "position = [0, inf, 0]")), 12,
                   "position");
}

TEST_F(CliTest, NonUnitQuaternionIsBadInput)
{
    expectBadInput(writeScenario("quat.toml", sceneWith(13, "orientation = [1, 1, 0, 0]")), 13,
                   "orientation");
}

TEST_F(CliTest, ImpulseOnUnknownBodyIsBadInput)
{
    const std::string file = writeScenario(
        "body.toml", sceneWith(0, "",
                               {"", "[[impulse]]", "at = 0.1", "body = \"nobody\"",
                                "impulse = [1, 0, 0]", "offset = [0, 0, 0]"}));
    expectBadInput(file, 17, "body");
    EXPECT_NE(runTumble({"run", file}).output.find("nobody"), std::string::npos);
}

TEST_F(CliTest, UnreachableTargetIsBadInput)
{
    // at t = 0 the body is still; a spin with no change of velocity needs a pure torque
    const std::string file = writeScenario(
        "target.toml", sceneWith(0, "",
                                 {"", "[[impulse]]", "at = 0.0", "body = \"rb\"",
                                  "velocity = [0, 0, 0]", "angular_velocity = [0, 0, 1]"}));
    const Result result = runTumble({"run", file}, Capture::StderrOnly);
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find("tumble: error: " + file + ":15:"), std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("impulse[0]"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("cannot be reached by one impulse"), std::string::npos)
        << result.output;
    EXPECT_EQ(runTumble({"check", file}).exitCode, 2);
}

TEST_F(CliTest, NonPositiveDtIsBadInput)
{
    expectBadInput(writeScenario("dt0.toml", sceneWith(2, "dt = 0.0")), 2, "dt");
    expectBadInput(writeScenario("dtneg.toml", sceneWith(2, "dt = -0.01")), 2, "dt");
}

TEST_F(CliTest, BadOverrideIsBadInput)
{
    const std::string file = writeScenario("good.toml", sceneWith(0, ""));
    const Result result = runTumble({"run", file, "--dt", "-1"}, Capture::StderrOnly);
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find("dt"), std::string::npos) << result.output;
    EXPECT_EQ(runTumble({"run", file, "--set", "rb.mass=0"}).exitCode, 2);
    EXPECT_EQ(runTumble({"run", file, "--set", "nobody.mass=1"}).exitCode, 2);
}

TEST_F(CliTest, UsageErrorsExitWithTwo)
{
    EXPECT_EQ(runTumble({}).exitCode, 2);
    EXPECT_EQ(runTumble({"frobnicate"}).exitCode, 2);
    EXPECT_EQ(runTumble({"run"}).exitCode, 2);
    EXPECT_EQ(runTumble({"run", "x.toml", "--every", "0"}).exitCode, 2);
    EXPECT_EQ(runTumble({"run", "x.toml", "--no-such-option"}).exitCode, 2);
    EXPECT_EQ(runTumble({"--help"}).exitCode, 0);
}

TEST_F(CliTest, PrintsInverseInertiaInGlmFormat)
{
    const Result result =
        runTumble({"run", (kScenarioDir / "part3_task1_impulse.toml").string()});
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("mat3x3((0.150000, 0.000000, 0.000000), "
                                 "(0.000000, 0.750000, 0.000000), "
                                 "(0.000000, 0.000000, 0.150000))"),
              std::string::npos)
        << result.output;
    EXPECT_NE(result.output.find("(solved for target)"), std::string::npos) << result.output;
}

TEST_F(CliTest, SetOverridesChangeTheRun)
{
    const std::string file = (kScenarioDir / "part3_task1_impulse.toml").string();
    const Result lighter = runTumble({"run", file, "--set", "rb.mass=1"});
    EXPECT_EQ(lighter.exitCode, 0) << lighter.output;
    EXPECT_NE(lighter.output.find("mat3x3((0.300000, 0.000000, 0.000000), "
                                  "(0.000000, 1.500000, 0.000000), "
                                  "(0.000000, 0.000000, 0.300000))"),
              std::string::npos)
        << lighter.output;

    const Result shorter = runTumble({"run", file, "--duration", "1", "--quiet"});
    EXPECT_EQ(shorter.exitCode, 0) << shorter.output;
    EXPECT_NE(shorter.output.find("final state at t = 1.000000 s"), std::string::npos)
        << shorter.output;
    const Result viaSet = runTumble({"run", file, "--set", "world.duration=1", "--quiet"});
    EXPECT_EQ(viaSet.output, shorter.output);
}

TEST_F(CliTest, QuietDropsEventLines)
{
    const std::string file = (kScenarioDir / "part3_task4_friction.toml").string();
    const Result loud = runTumble({"run", file});
    const Result quiet = runTumble({"run", file, "--quiet"});
    EXPECT_EQ(loud.exitCode, 0) << loud.output;
    EXPECT_EQ(quiet.exitCode, 0) << quiet.output;
    EXPECT_NE(loud.output.find("hits the ground"), std::string::npos) << loud.output;
    EXPECT_EQ(quiet.output.find("hits the ground"), std::string::npos) << quiet.output;
    EXPECT_NE(quiet.output.find("final state"), std::string::npos) << quiet.output;
}

TEST_F(CliTest, CsvHasHeaderAndOneRowPerBodyPerSample)
{
    const std::string file = writeScenario("good.toml", sceneWith(0, ""));
    const fs::path csv = dir() / "out.csv";
    // 0.5 s at dt = 0.01 is 50 steps: samples at steps 0, 7, 14, ..., 49, and the final state at
    // step 50 (issue 14, item 12: --every N still writes the final row) -> 9 rows
    const Result result = runTumble({"run", file, "--csv", csv.string(), "--every", "7"});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const std::vector<std::string> rows = lines(readFile(csv));
    ASSERT_EQ(rows.size(), 1u + 9u);
    EXPECT_EQ(rows.back().rfind("0.5,rb,", 0), 0u) << rows.back();
    EXPECT_EQ(rows[0], "time,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic,potential");
    EXPECT_EQ(rows[1].rfind("0,rb,0,5,0,1,0,0,0,0,0,0,0,0,0,0,", 0), 0u) << rows[1];
    EXPECT_EQ(rows[2].rfind("0.070000000000000007,rb,", 0), 0u) << rows[2];
    EXPECT_FALSE(fs::exists(dir() / "out.csv.tmp"));
}

TEST_F(CliTest, CsvToStdoutKeepsTheConsoleOffStdout)
{
    const std::string file = writeScenario("good.toml", sceneWith(0, ""));
    const Result result = runTumble({"run", file, "--csv", "-", "--every", "10"},
                                    Capture::StdoutOnly);
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const std::vector<std::string> rows = lines(result.output);
    ASSERT_EQ(rows.size(), 1u + 6u) << result.output;
    EXPECT_EQ(rows[0], "time,body,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic,potential");
}

/// x of the body in the last CSV row.
double finalX(const std::string& csvText)
{
    const std::vector<std::string> rows = lines(csvText);
    std::istringstream row(rows.back());
    std::string time;
    std::string body;
    std::string x;
    std::getline(row, time, ',');
    std::getline(row, body, ',');
    std::getline(row, x, ',');
    return std::stod(x);
}

TEST_F(CliTest, ImpulsesActAtTheirTimeInsideAStep)
{
    // no gravity, dt = 0.1: a push to 1 m/s at t = 0.25 (inside a step) or 0.3 (on a step
    // boundary) leaves the body at 1 - at after 1 s
    for (const auto& [at, expectedX] : {std::pair{"0.25", 0.75}, std::pair{"0.3", 0.7}}) {
        const std::string printedAt = std::to_string(std::stod(at));
        const std::string file = writeScenario(
            "split.toml", "[world]\ngravity = [0, 0, 0]\ndt = 0.1\nduration = 1.0\n\n"
                          "[[body]]\nname = \"rb\"\n\n[[impulse]]\nat = " +
                              std::string(at) +
                              "\nbody = \"rb\"\nimpulse = [1, 0, 0]\noffset = [0, 0, 0]\n");
        const fs::path csv = dir() / "split.csv";
        const Result result = runTumble({"run", file, "--csv", csv.string()});
        ASSERT_EQ(result.exitCode, 0) << result.output;
        EXPECT_NEAR(finalX(readFile(csv)), expectedX, 1e-12) << "at = " << at;
        EXPECT_NE(result.output.find("t = " + printedAt + " s  impulse[0] on rb"),
                  std::string::npos)
            << result.output;
    }
}

TEST_F(CliTest, SameScenarioGivesByteIdenticalCsv)
{
    const std::string file = (kScenarioDir / "part3_task4_friction.toml").string();
    const fs::path first = dir() / "first.csv";
    const fs::path second = dir() / "second.csv";
    ASSERT_EQ(runTumble({"run", file, "--quiet", "--csv", first.string()}).exitCode, 0);
    ASSERT_EQ(runTumble({"run", file, "--quiet", "--csv", second.string()}).exitCode, 0);
    const std::string a = readFile(first);
    EXPECT_GT(lines(a).size(), 100u);
    EXPECT_TRUE(a == readFile(second));
}

TEST_F(CliTest, EveryScenarioFileChecksOk)
{
    int checked = 0;
    for (const fs::directory_entry& entry : fs::directory_iterator(kScenarioDir)) {
        if (entry.path().extension() != ".toml") {
            continue;
        }
        const Result result = runTumble({"check", entry.path().string()});
        EXPECT_EQ(result.exitCode, 0) << entry.path() << ": " << result.output;
        EXPECT_NE(result.output.find(entry.path().string() + ": ok ("), std::string::npos)
            << result.output;
        ++checked;
    }
    EXPECT_GE(checked, 6);
}

TEST_F(CliTest, ValidatePassesEveryCaseAndWritesTheTable)
{
    const fs::path csv = dir() / "validation.csv";
    // The table only: the convergence study runs every case at five steps, which the library's
    // own tests cover (tests/validation); here the command's exit code and output are checked.
    const Result result =
        runTumble({"validate", "--no-study", "--csv", csv.string()}, Capture::StdoutOnly);
    EXPECT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(result.output.find("FAIL"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("intermediate axis"), std::string::npos);
    EXPECT_NE(result.output.find(" 0 failed"), std::string::npos);
    const std::vector<std::string> rows = lines(readFile(csv));
    ASSERT_GT(rows.size(), 40u);
    EXPECT_EQ(rows.front(), "case,quantity,dt,exact,value,error,tolerance,pass");
}

TEST_F(CliTest, EnergyLedgerBalancesAndContactLedgerListsEveryPoint)
{
    const fs::path energy = dir() / "energy.csv";
    const fs::path contacts = dir() / "contacts.csv";
    const Result result =
        runTumble({"run", (kScenarioDir / "part3_task4_friction.toml").string(), "--quiet",
                   "--energy-csv", energy.string(), "--contacts-csv", contacts.string()});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(result.output.find("warning"), std::string::npos) << result.output;

    const std::vector<std::string> energyRows = lines(readFile(energy));
    ASSERT_EQ(energyRows.size(), 2u + 2400u); // header, t = 0, one row per step
    for (std::size_t i = 1; i < energyRows.size(); ++i) {
        // the last column is total + removed - added - initial
        const double balance = std::stod(energyRows[i].substr(energyRows[i].rfind(',') + 1));
        ASSERT_LT(std::abs(balance), 1e-9 * 100.0) << energyRows[i];
    }

    const std::vector<std::string> contactRows = lines(readFile(contacts));
    ASSERT_GT(contactRows.size(), 100u);
    EXPECT_EQ(contactRows.front().substr(0, 26), "time,body,phase,vertex,px,");
    int impacts = 0;
    for (const std::string& row : contactRows) {
        impacts += row.find(",impact,") != std::string::npos ? 1 : 0;
    }
    EXPECT_GT(impacts, 0);
}

TEST_F(CliTest, PlotDrawsAPngOfALedger)
{
    const fs::path energy = dir() / "energy.csv";
    ASSERT_EQ(runTumble({"run", (kScenarioDir / "face_down_drop.toml").string(), "--quiet",
                         "--energy-csv", energy.string()})
                  .exitCode,
              0);
    const Result result = runTumble({"plot", energy.string()});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const std::string png = readFile(dir() / "energy.png");
    ASSERT_GT(png.size(), 1000u);
    EXPECT_EQ(png.substr(1, 3), "PNG");
}

TEST_F(CliTest, PlotRejectsAFileThatIsNotTumbleCsv)
{
    const std::string path = writeScenario("other.csv", "a,b,c\n1,2,3\n");
    const Result result = runTumble({"plot", path}, Capture::StderrOnly);
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find("unknown header"), std::string::npos) << result.output;
}

TEST(CliRun, OneAndTwoThreadsWriteByteIdenticalCsv)
{
    // 100 tumbling cuboids (scenarios/s4_tumbling_cuboids.toml) over 3 s: impacts, sliding and
    // sleep in several batches of the threaded step.
    const fs::path dir = fs::temp_directory_path() / "tumble_cli_threads";
    fs::create_directories(dir);
    const fs::path scenario = kScenarioDir / "s4_tumbling_cuboids.toml";
    std::vector<std::string> csvs;
    for (const std::string threads : {"1", "2"}) {
        const fs::path csv = dir / ("threads" + threads + ".csv");
        const Result result = runTumble({"run", scenario.string(), "--quiet", "--duration", "3",
                                         "--threads", threads, "--csv", csv.string()});
        ASSERT_EQ(result.exitCode, 0) << result.output;
        csvs.push_back(readFile(csv));
    }
    EXPECT_GT(csvs[0].size(), 100u * 720u * 20u);
    EXPECT_TRUE(csvs[0] == csvs[1]);
    EXPECT_EQ(runTumble({"run", scenario.string(), "--threads", "-1"}).exitCode, 2);
}

} // namespace
