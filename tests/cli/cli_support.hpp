// Helpers of the end-to-end tests of the tumble program: run it, read what it wrote, and a fresh
// directory per test.
#pragma once

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace tumble::cli_test {

namespace fs = std::filesystem;

inline const fs::path kScenarioDir = TUMBLE_SCENARIO_DIR;

/// Exit code and captured output of one run of the program.
struct Result {
    int exitCode = -1;
    std::string output;
};

inline std::string quoted(const std::string& text)
{
    std::string result = "'";
    for (const char c : text) {
        result += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return result + "'";
}

enum class Capture { Both, StdoutOnly, StderrOnly };

/// Runs `tumble` with the given arguments (each quoted for the shell).
inline Result runTumble(const std::vector<std::string>& arguments, Capture capture = Capture::Both)
{
    std::string command = quoted(TUMBLE_EXE);
    for (const std::string& argument : arguments) {
        command += ' ';
        command += quoted(argument);
    }
    switch (capture) {
    case Capture::Both:
        command += " 2>&1";
        break;
    case Capture::StdoutOnly:
        command += " 2>/dev/null";
        break;
    case Capture::StderrOnly:
        command += " 2>&1 >/dev/null";
        break;
    }

    Result result;
    std::FILE* pipe = popen(command.c_str(), "r");
    if (pipe == nullptr) {
        ADD_FAILURE() << "popen failed for " << command;
        return result;
    }
    std::array<char, 4096> buffer{};
    std::size_t count = 0;
    while ((count = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
        result.output.append(buffer.data(), count);
    }
    const int status = pclose(pipe);
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

inline Result runTumble(std::initializer_list<std::string> arguments, Capture capture = Capture::Both)
{
    return runTumble(std::vector<std::string>(arguments), capture);
}

inline std::string readFile(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline std::vector<std::string> lines(const std::string& text)
{
    std::vector<std::string> result;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        result.push_back(line);
    }
    return result;
}

/// A fresh directory per test, removed afterwards.
class CliTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir = fs::temp_directory_path() /
                ("tumble_cli_" + std::string(info->name()) + "_" + std::to_string(getpid()));
        fs::remove_all(m_dir);
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }

    /// Writes `text` to a file in the test's directory and returns its path.
    std::string writeScenario(const std::string& name, const std::string& text) const
    {
        const fs::path path = m_dir / name;
        std::ofstream(path, std::ios::binary) << text;
        return path.string();
    }

    [[nodiscard]] const fs::path& dir() const { return m_dir; }

private:
    fs::path m_dir;
};

} // namespace tumble::cli_test
