// End-to-end tests of `tumble throw`: the table, identical summaries whatever the thread count or
// number of MPI ranks, replay files that `tumble run` reproduces, and bad input.
#include "cli_support.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <string>

namespace {

using namespace tumble::cli_test;

const std::string kDiceCube = (kScenarioDir / "dice_cube.toml").string();

TEST_F(CliTest, ThrowPrintsTheFaceTableWithIntervalsAndChiSquare)
{
    const Result result = runTumble({"throw", kDiceCube, "--throws", "60", "--threads", "2"},
                                    Capture::StdoutOnly);
    ASSERT_EQ(result.exitCode, 0) << result.output;
    for (const char* face : {"+x ", "-x ", "+y ", "-y ", "+z ", "-z "}) {
        EXPECT_NE(result.output.find(std::string("\n") + face), std::string::npos) << face;
    }
    EXPECT_NE(result.output.find("95% interval (Wilson)"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("unsettled"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("chi-square test of uniformity"), std::string::npos)
        << result.output;
    // no progress bar when stderr is not a terminal
    const Result errors = runTumble({"throw", kDiceCube, "--throws", "20"}, Capture::StderrOnly);
    EXPECT_EQ(errors.output, "");
}

TEST_F(CliTest, ThrowChiSquareOnlyForACube)
{
    const Result result =
        runTumble({"throw", kDiceCube, "--throws", "20", "--set", "die.size=[0.02, 0.03, 0.02]"},
                  Capture::StdoutOnly);
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(result.output.find("chi-square"), std::string::npos) << result.output;
}

TEST_F(CliTest, ThrowSummaryAndCsvAreByteIdenticalForOneAndTwoThreads)
{
    const fs::path json1 = dir() / "one.json";
    const fs::path json2 = dir() / "two.json";
    const fs::path csv1 = dir() / "one.csv";
    const fs::path csv2 = dir() / "two.csv";
    ASSERT_EQ(runTumble({"throw", kDiceCube, "--throws", "150", "--seed", "77", "--threads", "1",
                         "--summary-json", json1.string(), "--csv", csv1.string()})
                  .exitCode,
              0);
    ASSERT_EQ(runTumble({"throw", kDiceCube, "--throws", "150", "--seed", "77", "--threads", "2",
                         "--summary-json", json2.string(), "--csv", csv2.string()})
                  .exitCode,
              0);
    const std::string summary = readFile(json1);
    EXPECT_TRUE(std::regex_match(
        summary, std::regex(R"(\{"throws": 150, "faces": \{"\+x": \d+, "-x": \d+, "\+y": \d+, )"
                            R"("-y": \d+, "\+z": \d+, "-z": \d+\}, "unsettled": \d+, )"
                            R"("seed": 77\}\n)")))
        << summary;
    EXPECT_EQ(summary, readFile(json2));
    const std::string csv = readFile(csv1);
    EXPECT_EQ(lines(csv).size(), 151u);
    EXPECT_EQ(lines(csv).front(), "index,face,rest_time,x,y,z,vx,vy,vz,wx,wy,wz,qw,qx,qy,qz");
    EXPECT_EQ(csv, readFile(csv2));
    // another seed gives other throws
    const fs::path json3 = dir() / "three.json";
    ASSERT_EQ(runTumble({"throw", kDiceCube, "--throws", "150", "--seed", "78", "--csv",
                         (dir() / "three.csv").string(), "--summary-json", json3.string()})
                  .exitCode,
              0);
    EXPECT_NE(readFile(dir() / "three.csv"), csv);
}

#ifdef TUMBLE_MPIEXEC
TEST_F(CliTest, ThrowUnderMpirunGivesTheSameSummaryAndCsvAsOneProcess)
{
    const fs::path single = dir() / "single.json";
    const fs::path ranks = dir() / "ranks.json";
    ASSERT_EQ(runTumble({"throw", kDiceCube, "--throws", "101", "--seed", "5", "--threads", "1",
                         "--summary-json", single.string(), "--csv",
                         (dir() / "single.csv").string()})
                  .exitCode,
              0);
    // run as root in CI containers: Open MPI refuses root unless told, and 2 ranks may exceed
    // the slots it detects
    const std::string command = std::string("'") + TUMBLE_MPIEXEC +
                                "' -n 2 --oversubscribe --allow-run-as-root '" + TUMBLE_EXE +
                                "' throw '" + kDiceCube + "' --throws 101 --seed 5 --threads 1 " +
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
    // only rank 0 prints: one table
    EXPECT_EQ(output.find("chi-square"), output.rfind("chi-square")) << output;
    EXPECT_EQ(readFile(ranks), readFile(single));
    EXPECT_EQ(readFile(dir() / "ranks.csv"), readFile(dir() / "single.csv"));
}
#endif

TEST_F(CliTest, ThrowReplayRunsToTheSameFaceAndRestTime)
{
    for (const char* index : {"0", "3", "8"}) {
        SCOPED_TRACE(index);
        const fs::path out = dir() / (std::string("throw") + index + ".toml");
        const Result replay = runTumble(
            {"throw", kDiceCube, "--seed", "9", "--replay", index, "--out", out.string()});
        ASSERT_EQ(replay.exitCode, 0) << replay.output;
        std::smatch thrown;
        ASSERT_TRUE(std::regex_search(replay.output, thrown,
                                      std::regex(R"(came to rest at t = ([0-9.e+-]+) s on face (\S+))")))
            << replay.output;
        const Result run = runTumble({"run", out.string()}, Capture::StdoutOnly);
        ASSERT_EQ(run.exitCode, 0) << run.output;
        std::smatch ran;
        ASSERT_TRUE(std::regex_search(run.output, ran,
                                      std::regex(R"(die came to rest at t = ([0-9.]+) s on face (\S+))")))
            << run.output;
        EXPECT_EQ(ran[2].str(), thrown[2].str());
        // tumble run prints six decimals
        char printed[32];
        std::snprintf(printed, sizeof printed, "%.6f", std::stod(thrown[1].str()));
        EXPECT_EQ(ran[1].str(), printed);
        // the replay is an ordinary scenario: no [throw] table
        EXPECT_EQ(readFile(out).find("[throw]"), std::string::npos);
    }
}

/// Expects exit code 2 and one "tumble: error: ..." line naming `fragment`.
void expectThrowBadInput(std::initializer_list<std::string> arguments, const std::string& fragment)
{
    const Result result = runTumble(arguments, Capture::StderrOnly);
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find(fragment), std::string::npos) << result.output;
    EXPECT_EQ(lines(result.output).size(), 1u) << result.output;
}

TEST_F(CliTest, ThrowBadValuesExitWithTwoNamingTheKey)
{
    const std::string bad = writeScenario("bad.toml", "[ground]\n[[body]]\nsize = [0.02, 0.02, 0.02]\n"
                                                      "[throw]\nheight = [1.0, 0.5]\n");
    expectThrowBadInput({"throw", bad}, bad + ":5: throw.height: min must be <= max");
    expectThrowBadInput({"throw", kDiceCube, "--set", "throw.height=[-1, 1]"},
                        "--set: throw.height: must be >= 0");
    expectThrowBadInput({"throw", kDiceCube, "--set", "throw.max_time=0"},
                        "--set: throw.max_time: must be > 0");
    const std::string twoBodies = writeScenario(
        "two.toml", "[ground]\n[[body]]\nposition = [-5, 2, 0]\n[[body]]\n"
                    "position = [5, 2, 0]\n[throw]\nheight = 3\n");
    expectThrowBadInput({"throw", twoBodies}, twoBodies + ":6: throw: several dice need a region");
    const std::string unknown =
        writeScenario("unknown.toml", "[ground]\n[[body]]\n[throw]\nheight = 3\nspin = 2\n");
    expectThrowBadInput({"throw", unknown}, unknown + ":5: throw.spin: unknown key 'spin'");
    expectThrowBadInput({"throw", (kScenarioDir / "face_down_drop.toml").string()},
                        "throw: missing: tumble throw needs a [throw] table");
    expectThrowBadInput({"throw", kDiceCube, "--replay", "2"}, "--replay I and --out");
}

TEST_F(CliTest, ThrowCountMustBePositive)
{
    for (const char* count : {"0", "-5"}) {
        const Result result = runTumble({"throw", kDiceCube, "--throws", count});
        EXPECT_EQ(result.exitCode, 2) << result.output;
        EXPECT_NE(result.output.find("--throws"), std::string::npos) << result.output;
    }
}

} // namespace
