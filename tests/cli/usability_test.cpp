// End-to-end tests of what a new user trips over (issue 14): thread counts, command-line
// messages, printed digits, plots, signals, clashing outputs and the end time of a run.
#include "cli_support.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
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

// item 17: an error in the value of --dt or --duration names that option, not --set
TEST(CliMessages, TheShorthandsNameThemselvesInErrors)
{
    expectUsageError({"run", kFriction, "--dt", "abc"},
                     "--dt: must be a number above 0, got 'abc'");
    expectUsageError({"run", kFriction, "--dt", "10"},
                     "--dt: must be between 1e-06 and 0.1 s, got 10");
    expectUsageError({"run", kFriction, "--duration", "abc"},
                     "--duration: must be a number above 0, got 'abc'");
    expectUsageError({"run", kFriction, "--dt", "1e-6", "--duration", "1e5"},
                     "--duration: the number of steps duration / dt must be at most");
    // a value given with --set keeps naming --set
    expectUsageError({"run", kFriction, "--set", "world.dt=abc"},
                     "--set: world.dt: expected a number");
    // a number the option takes is passed on as a number, whatever its spelling
    const Result spelled =
        runTumble({"run", kFriction, "--quiet", "--dt", ".05", "--duration", ".1"});
    EXPECT_EQ(spelled.exitCode, 0) << spelled.output;
    EXPECT_NE(spelled.output.find("dt = 0.05 s"), std::string::npos) << spelled.output;
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

namespace {

using namespace tumble::cli_test;

/// Runs `tumble` with PATH set to `path` only for that run.
Result runWithPath(const std::string& path, std::initializer_list<std::string> arguments)
{
    const std::string saved = std::getenv("PATH") != nullptr ? std::getenv("PATH") : "";
    setenv("PATH", path.c_str(), 1);
    Result result = runTumble(arguments, Capture::StderrOnly);
    setenv("PATH", saved.c_str(), 1);
    return result;
}

/// A stand-in for gnuplot in `folder` that saves its standard input (the script) to `saved` and
/// exits with `exitCode`.
void writeFakeGnuplot(const fs::path& folder, const fs::path& saved, int exitCode)
{
    fs::create_directories(folder);
    const fs::path program = folder / "gnuplot";
    std::ofstream(program) << "#!/bin/sh\ncat > '" << saved.string() << "'\nexit " << exitCode
                           << "\n";
    fs::permissions(program, fs::perms::owner_all);
}

class CliPlot : public CliTest {
protected:
    /// The multi-body impulse scenario's state and energy CSV files.
    void writeImpulseCsv()
    {
        const Result run = runTumble({"run", (kScenarioDir / "part2_task2_impulses.toml").string(),
                                      "--quiet", "--csv", (dir() / "imp.csv").string(),
                                      "--energy-csv", (dir() / "impe.csv").string()});
        ASSERT_EQ(run.exitCode, 0) << run.output;
    }
};

// item 2: a CSV of several bodies gets one curve per body, or the one --body names
TEST_F(CliPlot, SeveralBodiesGiveOneCurvePerBody)
{
    writeImpulseCsv();
    const fs::path script = dir() / "script.gp";
    writeFakeGnuplot(dir() / "bin", script, 0);
    const std::string path = (dir() / "bin").string() + ":/usr/bin:/bin";
    const Result result = runWithPath(path, {"plot", (dir() / "imp.csv").string()});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const std::string text = readFile(script);
    // each body's rows in a data block of its own, each drawn as a curve titled by its name
    for (const std::string body : {"left", "left_spin", "stop", "reverse", "stop_spin", "stop_all"}) {
        EXPECT_NE(text.find("title '" + body + "'"), std::string::npos) << body << "\n" << text;
    }
    EXPECT_NE(text.find("$body5 << EOD"), std::string::npos) << text;
    EXPECT_EQ(text.find("NaN"), std::string::npos) << text;

    const Result one =
        runWithPath(path, {"plot", (dir() / "impe.csv").string(), "--body", "stop_spin"});
    ASSERT_EQ(one.exitCode, 0) << one.output;
    const std::string picked = readFile(script);
    EXPECT_NE(picked.find("Energy ledger of stop_spin"), std::string::npos) << picked;
    EXPECT_EQ(picked.find("$body0 << EOD"), std::string::npos) << picked;

    const Result unknown =
        runWithPath(path, {"plot", (dir() / "imp.csv").string(), "--body", "nobody"});
    EXPECT_EQ(unknown.exitCode, 2) << unknown.output;
    EXPECT_NE(unknown.output.find("tumble: error: --body: no body named \"nobody\""),
              std::string::npos)
        << unknown.output;
}

TEST_F(CliPlot, SeveralBodiesDrawAPngWithGnuplot)
{
    writeImpulseCsv();
    const Result result = runTumble({"plot", (dir() / "imp.csv").string(),
                                     (dir() / "impe.csv").string()});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_EQ(readFile(dir() / "imp.png").substr(1, 3), "PNG");
    EXPECT_EQ(readFile(dir() / "impe.png").substr(1, 3), "PNG");
}

// item 3: gnuplot runs without a shell, takes any file name, and failures say why
TEST_F(CliPlot, FileNamesReachNoShell)
{
    writeImpulseCsv();
    const std::string csv = readFile(dir() / "imp.csv");
    for (const std::string name : {"a';touch INJECTED;'b.csv", "it's.csv", "$(touch X).csv"}) {
        std::ofstream(dir() / name) << csv;
        const Result result = runTumble({"plot", (dir() / name).string(), "--out", dir().string()});
        EXPECT_EQ(result.exitCode, 0) << name << ": " << result.output;
        fs::path png = dir() / name;
        png.replace_extension(".png");
        EXPECT_EQ(readFile(png).substr(1, 3), "PNG") << name;
    }
    EXPECT_FALSE(fs::exists("INJECTED"));
    EXPECT_FALSE(fs::exists(dir() / "INJECTED"));
    EXPECT_FALSE(fs::exists("X"));
}

TEST_F(CliPlot, AFailureGivesTheRealReason)
{
    writeImpulseCsv();
    const std::string csv = (dir() / "imp.csv").string();
    const Result missing = runWithPath((dir() / "empty").string(), {"plot", csv});
    EXPECT_NE(missing.exitCode, 0);
    EXPECT_NE(missing.output.find("cannot run gnuplot: No such file or directory"),
              std::string::npos)
        << missing.output;

    writeFakeGnuplot(dir() / "bin", dir() / "script.gp", 3);
    const Result failed = runWithPath((dir() / "bin").string(), {"plot", csv});
    EXPECT_NE(failed.exitCode, 0);
    EXPECT_NE(failed.output.find("gnuplot failed with exit status 3"), std::string::npos)
        << failed.output;

    // item 17: a missing CSV says so, with exit 2
    const Result absent = runTumble({"plot", (dir() / "absent.csv").string()}, Capture::StderrOnly);
    EXPECT_EQ(absent.exitCode, 2);
    EXPECT_NE(absent.output.find("cannot open CSV: No such file or directory"), std::string::npos)
        << absent.output;
}

// item 21: validate --plot draws the study, so it is refused with --no-study instead of writing
// nothing; each series of convergence.png has a colour and point type of its own
TEST_F(CliPlot, ValidatePlotNeedsTheStudyAndGivesEachSeriesItsOwnLook)
{
    const fs::path plots = dir() / "plots";
    expectUsageError({"validate", "--no-study", "--plot", plots.string()},
                     "--plot: the plot draws the convergence study, which --no-study leaves out");
    EXPECT_FALSE(fs::exists(plots));

    const fs::path script = dir() / "script.gp";
    writeFakeGnuplot(dir() / "bin", script, 0);
    const Result result = runWithPath((dir() / "bin").string() + ":/usr/bin:/bin",
                                      {"validate", "--plot", plots.string()});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const std::string text = readFile(script);
    const std::string plot = text.substr(text.find("\nplot ") + 1);
    const std::string clauses = plot.substr(0, plot.find('\n'));
    std::set<std::string> looks;
    std::size_t series = 0;
    for (std::size_t at = clauses.find("'-' using"); at != std::string::npos;
         at = clauses.find("'-' using", at + 1)) {
        ++series;
        const std::size_t colour = clauses.find("lc rgb '", at);
        const std::size_t title = clauses.find(" title ", at);
        ASSERT_LT(colour, title) << clauses;
        looks.insert(clauses.substr(colour, title - colour));
    }
    EXPECT_GT(series, 8u) << "more series than gnuplot's default colours\n" << clauses;
    EXPECT_EQ(looks.size(), series) << clauses;
}

// item 17: an output plot cannot write is exit 3 with the system's reason on one line, before
// gnuplot runs, and no image data reaches the terminal
TEST_F(CliPlot, AnUnwritableOutputIsExitThreeWithTheReason)
{
    if (!fs::is_directory("/sys/kernel")) {
        GTEST_SKIP() << "needs /sys/kernel, a folder where no file can be made, even by root";
    }
    writeImpulseCsv();
    const Result result =
        runTumble({"plot", (dir() / "imp.csv").string(), "--out", "/sys/kernel"}, Capture::Both);
    EXPECT_EQ(result.exitCode, 3) << result.output;
    EXPECT_EQ(lines(result.output).size(), 1u) << result.output;
    EXPECT_EQ(result.output.rfind("tumble: error: cannot write /sys/kernel/imp.png", 0), 0u)
        << result.output;
    EXPECT_NE(result.output.find(": Permission denied"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find("PNG"), std::string::npos) << result.output;
}

} // namespace

namespace {

using namespace tumble::cli_test;

// item 9: a body inside the ground is bad input for run and check alike, with file, line, body
TEST(CliGround, ABuriedBodyIsRejectedByRunAndCheck)
{
    const std::string file = (kScenarioDir / "face_down_drop.toml").string();
    for (const char* command : {"run", "check"}) {
        const Result result =
            runTumble({command, file, "--set", "ground.height=5"}, Capture::StderrOnly);
        EXPECT_EQ(result.exitCode, 2) << result.output;
        EXPECT_EQ(lines(result.output).size(), 1u) << result.output;
        EXPECT_NE(result.output.find("tumble: error: " + file + ":"), std::string::npos)
            << result.output;
        EXPECT_NE(result.output.find("body[0].position: "), std::string::npos) << result.output;
        EXPECT_NE(result.output.find("below the ground (y = 5 m)"), std::string::npos)
            << result.output;
        EXPECT_NE(result.output.find("(body \"cube\")"), std::string::npos) << result.output;
    }
}

} // namespace

namespace {

using namespace tumble::cli_test;

// item 11: an output may not overwrite the input or another output; nothing runs
TEST_F(CliTest, OutputsMayNotOverwriteTheInputOrEachOther)
{
    const std::string scene = readFile(kScenarioDir / "face_down_drop.toml");
    const std::string copy = writeScenario("copy.toml", scene);
    const Result input = runTumble({"run", copy, "--quiet", "--csv", copy}, Capture::StderrOnly);
    EXPECT_EQ(input.exitCode, 2) << input.output;
    EXPECT_NE(input.output.find("tumble: error: --csv: " + copy + " is the scenario file"),
              std::string::npos)
        << input.output;
    EXPECT_EQ(readFile(copy), scene) << "the scenario was replaced";

    const std::string csv = (dir() / "s.csv").string();
    const std::string sameCsv = (dir() / "." / "s.csv").string();
    const Result twice =
        runTumble({"run", copy, "--quiet", "--csv", csv, "--energy-csv", sameCsv},
                  Capture::StderrOnly);
    EXPECT_EQ(twice.exitCode, 2) << twice.output;
    EXPECT_NE(twice.output.find("tumble: error: --energy-csv: "), std::string::npos)
        << twice.output;
    EXPECT_NE(twice.output.find("also the path of --csv"), std::string::npos) << twice.output;
    EXPECT_FALSE(fs::exists(csv));

    const Result dice = runTumble({"throw", kDice, "--throws", "2", "--csv", kDice},
                                  Capture::StderrOnly);
    EXPECT_EQ(dice.exitCode, 2) << dice.output;
    // /dev/null may take several outputs
    EXPECT_EQ(runTumble({"run", copy, "--quiet", "--csv", "/dev/null", "--energy-csv",
                         "/dev/null"})
                  .exitCode,
              0);
}

// item 12: a duration that is not a multiple of dt ends at the duration, final CSV row included
TEST_F(CliTest, ARunEndsAtItsDurationEvenBetweenSteps)
{
    const std::string csv = (dir() / "end.csv").string();
    const Result result = runTumble({"run", (kScenarioDir / "face_down_drop.toml").string(),
                                     "--dt", "0.1", "--duration", "0.25", "--quiet", "--csv", csv,
                                     "--every", "2"});
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("final state at t = 0.250000 s"), std::string::npos)
        << result.output;
    const std::vector<std::string> rows = lines(readFile(csv));
    ASSERT_EQ(rows.size(), 4u) << readFile(csv);
    EXPECT_EQ(rows[1].substr(0, 2), "0,");
    EXPECT_EQ(rows[3].substr(0, 5), "0.25,") << rows[3];
    // a multiple of dt still ends on a whole step
    const Result whole = runTumble({"run", (kScenarioDir / "face_down_drop.toml").string(),
                                    "--dt", "0.1", "--duration", "0.3", "--quiet"});
    EXPECT_NE(whole.output.find("final state at t = 0.300000 s (3 steps)"), std::string::npos)
        << whole.output;
}

} // namespace

namespace {

using namespace tumble::cli_test;

// item 6: validate compares at whole seconds, so a dt that does not divide one is refused
TEST(CliValidate, AStepThatDoesNotDivideASecondIsRefused)
{
    expectUsageError({"validate", "--dt", "0.03", "--no-study"},
                     "--dt: the validation cases compare at whole seconds");
    const Result divides = runTumble({"validate", "--dt", "0.005", "--no-study"});
    EXPECT_NE(divides.exitCode, 2) << divides.output;
    EXPECT_NE(divides.output.find("validation at dt = 1/200 s"), std::string::npos);
}

} // namespace

namespace {

using namespace tumble::cli_test;

// item 17: a write that fails is reported with the system's reason, naming the file, in every
// command, however early in the run it failed (validate writes its CSV in one piece)
TEST(CliMessages, AFullDiskIsReportedWithTheSystemsReasonByEveryCommand)
{
    if (!fs::exists("/dev/full")) {
        GTEST_SKIP() << "needs /dev/full";
    }
    const std::string reason = "tumble: error: cannot write /dev/full: No space left on device\n";
    const std::vector<std::vector<std::string>> commands = {
        {"run", kFriction, "--quiet", "--csv", "/dev/full"},
        {"run", kFriction, "--quiet", "--energy-csv", "/dev/full"},
        {"run", kFriction, "--quiet", "--contacts-csv", "/dev/full"},
        {"throw", kDice, "--throws", "20", "--csv", "/dev/full"},
        {"validate", "--no-study", "--csv", "/dev/full"}};
    for (const std::vector<std::string>& command : commands) {
        const Result result = runTumble(command, Capture::StderrOnly);
        EXPECT_EQ(result.exitCode, 3) << command.front() << "\n" << result.output;
        EXPECT_EQ(result.output, reason) << command.front() << " " << command.back();
    }
    // the console on a full disk: its lines are written (and fail) one at a time
    const std::vector<std::string> consoles = {
        quoted(TUMBLE_EXE) + " run " + quoted(kFriction),
        quoted(TUMBLE_EXE) + " throw " + quoted(kDice) + " --throws 20",
        quoted(TUMBLE_EXE) + " validate --no-study"};
    for (const std::string& command : consoles) {
        std::FILE* pipe = popen((command + " 2>&1 >/dev/full").c_str(), "r");
        ASSERT_NE(pipe, nullptr);
        std::string output;
        for (int c = std::fgetc(pipe); c != EOF; c = std::fgetc(pipe)) {
            output += static_cast<char>(c);
        }
        const int status = pclose(pipe);
        EXPECT_EQ(WEXITSTATUS(status), 3) << command << "\n" << output;
        EXPECT_EQ(output, "tumble: error: cannot write standard output: No space left on device\n")
            << command;
    }
}

// items 17 and 21: view's image is PNG only (exit 2 for another name) and is opened before any
// window, so an output that cannot be written is exit 3 with the system's reason, as in run
TEST_F(CliTest, ViewScreenshotIsAWritablePng)
{
    const std::string jpg = (dir() / "x.jpg").string();
    expectUsageError({"view", "--screenshot", jpg},
                     "--screenshot: the capture is a PNG image, so the file name must end in .png");
    expectUsageError({"view", "--screenshot", "-"}, "--screenshot:");
    EXPECT_FALSE(fs::exists(jpg));

    const Result missing = runTumble({"view", "--screenshot", "/nonexistent/dir/x.png"},
                                     Capture::StderrOnly);
#ifdef TUMBLE_HAS_VIEWER
    EXPECT_EQ(missing.exitCode, 3) << missing.output;
    EXPECT_EQ(missing.output, "tumble: error: cannot write /nonexistent/dir/x.png.tmp: "
                              "No such file or directory\n");
#else
    // built without the viewer (the sanitizer build): view says so, before any output
    EXPECT_EQ(missing.exitCode, 2) << missing.output;
    EXPECT_NE(missing.output.find("built without the viewer"), std::string::npos)
        << missing.output;
#endif
}

// item 8: view --at has run's limits; the error comes before any window or capture
TEST_F(CliTest, ViewAtIsCheckedLikeARunsDuration)
{
    const std::string png = (dir() / "x.png").string();
    expectUsageError({"view", "--screenshot", png, "--at", "1e20"},
                     "--at: the number of steps --at / dt must be at most 1e+09");
    expectUsageError({"view", "--screenshot", png, "--at", "1e12"}, "--at:");
    expectUsageError({"view", "--screenshot", png, "--at", "nan"}, "--at: must be a number");
    expectUsageError({"view", "--screenshot", png, "--at", "inf"}, "--at: must be a number");
    EXPECT_FALSE(fs::exists(png));
}

TEST(CliMessages, AnImpactWithElasticityZeroSaysRestitutionAppliedAsTheContactsCsvDoes)
{
    // issue 14, item 10: at 6.3 m/s the approach is far above the threshold; with e = 0 the
    // impact is plastic because of e, not because it was slow
    const std::string scene = (kScenarioDir / "face_down_drop.toml").string();
    const Result plastic =
        runTumble({"run", scene, "--duration", "1", "--set", "cube.elasticity=0"},
                  Capture::StdoutOnly);
    EXPECT_EQ(plastic.exitCode, 0);
    EXPECT_NE(plastic.output.find("approach speed = 6.264184 m/s, restitution applied with "
                                  "elasticity 0 (a plastic impact)"),
              std::string::npos)
        << plastic.output;
    EXPECT_EQ(plastic.output.find("slower than the threshold"), std::string::npos);
    const Result bouncing = runTumble({"run", scene, "--duration", "1"}, Capture::StdoutOnly);
    EXPECT_NE(bouncing.output.find("approach speed = 6.264184 m/s, restitution applied\n"),
              std::string::npos);
}

TEST(CliMessages, CheckSaysWhatRunWouldAboutAnImpulseAfterTheEnd)
{
    // issue 14, item 19: an impulse after the end is reported by check as by run; overlapping
    // and buried bodies are load errors for both (ScenarioTomlErrors)
    const std::string scene = (kScenarioDir / "part3_task1_impulse.toml").string();
    const Result checked =
        runTumble({"check", scene, "--set", "world.duration=0.5", "--set", "impulse[0].at=2"},
                  Capture::StdoutOnly);
    EXPECT_EQ(checked.exitCode, 0);
    EXPECT_NE(checked.output.find("impulse[0] at t = 2.000000 s is after the end of the run"),
              std::string::npos)
        << checked.output;
}

TEST(CliMessages, ThrowRejectsSeedsOutOfRangeAndSaysNaWhenNothingSettled)
{
    // issue 14, item 13
    expectUsageError({"throw", kDice, "--throws", "3", "--seed", "-1"}, "--seed");
    expectUsageError({"throw", kDice, "--throws", "3", "--seed", "18446744073709551616"},
                     "--seed");
    EXPECT_EQ(runTumble({"throw", kDice, "--throws", "3", "--seed", "18446744073709551615"})
                  .exitCode,
              0);
    const Result unsettled =
        runTumble({"throw", kDice, "--throws", "3", "--set", "throw.max_time=0.01"});
    EXPECT_EQ(unsettled.exitCode, 0);
    EXPECT_NE(unsettled.output.find("n/a (no throw settled)"), std::string::npos)
        << unsettled.output;
    EXPECT_NE(unsettled.output.find("tumble: warning: no throw came to rest"), std::string::npos);
    EXPECT_EQ(unsettled.output.find("p = 1"), std::string::npos);
}

TEST(CliMessages, RunAndValidateDrawTheirProgressBarOnlyOnATerminal)
{
    // issue 14, item 15: the bar goes to stderr when it is a terminal; redirected, stderr stays
    // clean. On a terminal, `script -qc "tumble run ... --quiet" /dev/null` shows
    // "[####....] 291/600 steps  ... steps/s  ... s left".
    // a run of about a second, so the bar (redrawn every 0.2 s) has time to show: with sleep on,
    // the settled pyramid costs so little that the whole run takes about 0.2 s, and 30 s of it
    // awake take about that too
    const std::string scene = (kScenarioDir / "pyramid_55.toml").string();
    const Result run = runTumble(
        {"run", scene, "--quiet", "--duration", "150", "--set", "world.sleep=false"},
        Capture::StderrOnly);
    EXPECT_EQ(run.exitCode, 0);
    EXPECT_EQ(run.output.find("steps/s"), std::string::npos) << run.output;
    const Result validate = runTumble({"validate"}, Capture::StderrOnly);
    EXPECT_EQ(validate.output.find("runs/s"), std::string::npos) << validate.output;
    // on a terminal (script(1), from Debian's essential bsdutils, gives the run one)
    const std::string scripted = "script -qc \"" + std::string(TUMBLE_EXE) + " run " + scene +
                                 " --quiet --duration 150 --set world.sleep=false\" /dev/null 2>&1";
    FILE* pipe = popen(scripted.c_str(), "r");
    ASSERT_NE(pipe, nullptr);
    std::string text;
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) {
        text.append(buffer, n);
    }
    pclose(pipe);
    EXPECT_NE(text.find("steps/s"), std::string::npos) << text;
}

TEST(CliMessages, OneStepIsSingularAndABodyAtTheOriginHasNoNegativeZeroEnergy)
{
    // issue 14, item 21 (two of its blemishes)
    const std::string scene = (kScenarioDir / "part2_task2_impulses.toml").string();
    const Result one = runTumble({"run", scene, "--quiet", "--dt", "0.01", "--duration", "0.01"},
                                 Capture::StdoutOnly);
    EXPECT_NE(one.output.find("(1 step)"), std::string::npos) << one.output;
    EXPECT_NE(one.output.find("(1 step):"), std::string::npos) << one.output;
    EXPECT_EQ(one.output.find("(1 steps)"), std::string::npos);
    const Result csv = runTumble({"run", scene, "--quiet", "--csv", "-", "--duration", "0.01"},
                                 Capture::StdoutOnly);
    // the first body sits at the origin: its potential energy is 0, not -0
    EXPECT_NE(csv.output.find("\n0,left,0,0,0,1,0,0,0,0,0,0,0,0,0,0,0\n"), std::string::npos)
        << csv.output.substr(0, 300);
    EXPECT_EQ(csv.output.find(",-0\n"), std::string::npos);
}

} // namespace
