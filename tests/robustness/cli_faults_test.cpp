// The tumble program under faults: SIGINT/SIGTERM during a run, a full disk, an unwritable path,
// and --hash.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;

const std::string kScenario = std::string(TUMBLE_SCENARIO_DIR) + "/part3_task4_friction.toml";

struct Result {
    int exitCode = -1;
    std::string output;
};

std::string readFile(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

fs::path scratch(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / ("tumble_faults_" + std::to_string(getpid()));
    fs::create_directories(dir);
    return dir / name;
}

/// Starts tumble with `arguments`, stdout to `stdoutPath` and stderr to `stderrPath`.
pid_t start(const std::vector<std::string>& arguments, const std::string& stdoutPath,
            const std::string& stderrPath)
{
    const pid_t pid = fork();
    if (pid == 0) {
        std::freopen(stdoutPath.c_str(), "w", stdout);
        std::freopen(stderrPath.c_str(), "w", stderr);
        std::vector<char*> argv;
        std::string exe = TUMBLE_EXE;
        argv.push_back(exe.data());
        std::vector<std::string> copies = arguments;
        for (std::string& argument : copies) {
            argv.push_back(argument.data());
        }
        argv.push_back(nullptr);
        execv(exe.c_str(), argv.data());
        _exit(127);
    }
    return pid;
}

int waitFor(pid_t pid)
{
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
}

Result run(const std::vector<std::string>& arguments, const std::string& stdoutPath = "")
{
    const std::string out = stdoutPath.empty() ? scratch("out.txt").string() : stdoutPath;
    const std::string err = scratch("err.txt").string();
    const int code = waitFor(start(arguments, out, err));
    return {code, (stdoutPath.empty() ? readFile(out) : std::string()) + readFile(err)};
}

/// Every line has the header's number of fields and ends with a newline.
void expectCompleteCsv(const std::string& text)
{
    ASSERT_FALSE(text.empty());
    EXPECT_EQ(text.back(), '\n') << "torn last line";
    std::istringstream lines(text);
    std::string line;
    std::getline(lines, line);
    const auto fields = std::count(line.begin(), line.end(), ',');
    int rows = 0;
    while (std::getline(lines, line)) {
        EXPECT_EQ(std::count(line.begin(), line.end(), ','), fields) << line;
        ++rows;
    }
    EXPECT_GT(rows, 0);
}

/// Last value of the first column (time) of a CSV.
double lastTime(const std::string& text)
{
    const auto end = text.find_last_of('\n', text.size() - 2);
    return std::stod(text.substr(end + 1));
}

void expectStopsCleanlyOn(int signal, int expectedCode, const char* name)
{
    const fs::path csv = scratch(std::string("interrupted_") + name + ".csv");
    fs::remove(csv);
    // Sleep off: the box never rests, so the run would take hours.
    const pid_t pid = start({"run", kScenario, "--quiet", "--set", "world.sleep=false",
                             "--duration", "1e5", "--csv", csv.string()},
                            scratch("sig_out.txt").string(), scratch("sig_err.txt").string());
    const fs::path temporary = csv.string() + ".tmp";
    for (int i = 0; i < 200 && !(fs::exists(temporary) && fs::file_size(temporary) > 100000); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    kill(pid, signal);
    EXPECT_EQ(waitFor(pid), expectedCode);
    const std::string errors = readFile(scratch("sig_err.txt"));
    EXPECT_NE(errors.find(std::string("interrupted by ") + name + ": stopped at t = "),
              std::string::npos)
        << errors;
    ASSERT_TRUE(fs::exists(csv)) << "no complete file after the interrupt";
    EXPECT_FALSE(fs::exists(temporary));
    const std::string text = readFile(csv);
    expectCompleteCsv(text);
    // The last row is at the time the message names.
    const auto at = errors.find("stopped at t = ") + std::string("stopped at t = ").size();
    EXPECT_DOUBLE_EQ(lastTime(text), std::stod(errors.substr(at)));
    EXPECT_GT(lastTime(text), 0.0);
}

TEST(CliFaults, SigintStopsAtTheNextStepAndLeavesACompleteFile)
{
    expectStopsCleanlyOn(SIGINT, 130, "SIGINT");
}

TEST(CliFaults, SigtermStopsAtTheNextStepAndLeavesACompleteFile)
{
    expectStopsCleanlyOn(SIGTERM, 143, "SIGTERM");
}

// issue 14, item 7: GNU timeout signals the child and then its group, two SIGTERMs at once; they
// are one request, the console lines stay written and no .tmp is left behind
TEST(CliFaults, UnderTimeoutARunLeavesItsReportAndACompleteFile)
{
    const fs::path folder = scratch("under_timeout");
    fs::create_directories(folder);
    fs::remove(folder / "t.csv");
    const std::string command =
        "cd '" + folder.string() + "' && timeout 2 '" + std::string(TUMBLE_EXE) + "' run '" +
        std::string(TUMBLE_SCENARIO_DIR) +
        "/torque_free_top.toml' --duration 100000 --quiet --csv t.csv > t.out 2> t.err";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 124) << "timeout reports that it stopped the command";
    const std::string out = readFile(folder / "t.out");
    EXPECT_NE(out.find("scenario: "), std::string::npos) << out;
    EXPECT_NE(out.find("final state at t = "), std::string::npos) << out;
    EXPECT_NE(readFile(folder / "t.err").find("interrupted by SIGTERM"), std::string::npos);
    EXPECT_FALSE(fs::exists(folder / "t.csv.tmp"));
    ASSERT_TRUE(fs::exists(folder / "t.csv"));
    expectCompleteCsv(readFile(folder / "t.csv"));
}

TEST(CliFaults, AnInterruptedThrowReportsTheThrowsItFinished)
{
    // issue 14, item 14: Ctrl-C after thousands of throws keeps their counts, marked interrupted
    const fs::path folder = scratch("interrupted_throw");
    fs::create_directories(folder);
    fs::remove(folder / "s.json");
    const std::string command =
        "cd '" + folder.string() + "' && timeout --preserve-status -s INT 2 '" +
        std::string(TUMBLE_EXE) + "' throw '" + std::string(TUMBLE_SCENARIO_DIR) +
        "/dice_cube.toml' --throws 2000000 --threads 1 --summary-json s.json > t.out 2> t.err";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 130);
    const std::string out = readFile(folder / "t.out");
    EXPECT_NE(out.find("chi-square test of uniformity"), std::string::npos) << out;
    EXPECT_NE(readFile(folder / "t.err").find("interrupted by SIGINT after "), std::string::npos);
    const std::string json = readFile(folder / "s.json");
    EXPECT_NE(json.find("\"interrupted\": true"), std::string::npos) << json;
    EXPECT_EQ(json.find("\"throws\": 0,"), std::string::npos) << json;
}

TEST(CliFaults, TwoSignalsAtOnceAreOneRequest)
{
    const fs::path csv = scratch("two_at_once.csv");
    fs::remove(csv);
    const pid_t pid = start({"run", kScenario, "--quiet", "--set", "world.sleep=false",
                             "--duration", "1e5", "--csv", csv.string()},
                            scratch("two_out.txt").string(), scratch("two_err.txt").string());
    const fs::path temporary = csv.string() + ".tmp";
    for (int i = 0; i < 200 && !(fs::exists(temporary) && fs::file_size(temporary) > 100000); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    kill(pid, SIGINT);
    kill(pid, SIGINT);
    kill(pid, SIGTERM);
    EXPECT_EQ(waitFor(pid), 130);
    EXPECT_NE(readFile(scratch("two_out.txt")).find("final state at t = "), std::string::npos);
    EXPECT_FALSE(fs::exists(temporary));
    expectCompleteCsv(readFile(csv));
}

TEST(CliFaults, AFullDiskIsAClearErrorWithExitCodeThree)
{
    const Result csv = run({"run", kScenario, "--quiet", "--csv", "/dev/full"});
    EXPECT_EQ(csv.exitCode, 3) << csv.output;
    EXPECT_NE(csv.output.find("tumble: error: cannot write /dev/full: No space left on device"),
              std::string::npos)
        << csv.output;
    // The console report itself on a full disk.
    const Result console = run({"run", kScenario, "--quiet"}, "/dev/full");
    EXPECT_EQ(console.exitCode, 3) << console.output;
    EXPECT_NE(console.output.find("cannot write standard output"), std::string::npos)
        << console.output;
}

TEST(CliFaults, AnUnwritablePathIsAClearErrorWithExitCodeThree)
{
    const Result missing = run({"run", kScenario, "--quiet", "--csv", "/nonexistent/dir/x.csv"});
    EXPECT_EQ(missing.exitCode, 3);
    EXPECT_NE(missing.output.find("cannot write /nonexistent/dir/x.csv.tmp: No such file"),
              std::string::npos)
        << missing.output;
    // A directory in place of the file: the rename fails, the old directory stays.
    const fs::path directory = scratch("a_directory.csv");
    fs::create_directories(directory);
    const Result clash = run({"run", kScenario, "--quiet", "--csv", directory.string()});
    EXPECT_EQ(clash.exitCode, 3) << clash.output;
    EXPECT_TRUE(fs::is_directory(directory));
    if (geteuid() != 0) {
        // (root may write anywhere, so only a normal user can see this one)
        const fs::path readOnly = scratch("read_only");
        fs::create_directories(readOnly);
        chmod(readOnly.c_str(), 0555);
        const Result denied = run({"run", kScenario, "--quiet", "--csv", (readOnly / "x.csv").string()});
        EXPECT_EQ(denied.exitCode, 3);
        EXPECT_NE(denied.output.find("Permission denied"), std::string::npos) << denied.output;
    }
}

TEST(CliFaults, AFailedRunLeavesThePreviousFileUntouched)
{
    const fs::path csv = scratch("previous.csv");
    {
        std::ofstream(csv) << "previous content\n";
    }
    // A non-finite-free but failing run: the console output cannot be written.
    const Result failed = run({"run", kScenario, "--quiet", "--csv", csv.string()}, "/dev/full");
    EXPECT_EQ(failed.exitCode, 3);
    // The CSV itself was complete, so it was renamed into place before stdout failed, or the
    // previous one is still there: never a torn file.
    const std::string text = readFile(csv);
    EXPECT_TRUE(text == "previous content\n" || text.back() == '\n');
}

TEST(CliFaults, HashIsPrintedAndRepeatable)
{
    const Result first = run({"run", kScenario, "--quiet", "--hash"});
    const Result second = run({"run", kScenario, "--quiet", "--hash"});
    EXPECT_EQ(first.exitCode, 0);
    const auto at = first.output.find("state hash: ");
    ASSERT_NE(at, std::string::npos) << first.output;
    const std::string hash = first.output.substr(at + 12, 16);
    EXPECT_EQ(hash.find_first_not_of("0123456789abcdef"), std::string::npos) << hash;
    EXPECT_NE(second.output.find("state hash: " + hash), std::string::npos);
    // A different run, a different hash.
    const Result other = run({"run", kScenario, "--quiet", "--hash", "--duration", "1"});
    EXPECT_EQ(other.output.find("state hash: " + hash), std::string::npos);
}

} // namespace
