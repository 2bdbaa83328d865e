#include "cli_options.hpp"

#include <algorithm>
#include "console.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <system_error>
#include <thread>

namespace tumble::cli {
namespace {

/// The whole number in `text`, if all of it is one.
bool parseWholeNumber(const std::string& text, long long& value)
{
    if (text.empty()) {
        return false;
    }
    errno = 0;
    char* end = nullptr;
    value = std::strtoll(text.c_str(), &end, 10);
    return errno == 0 && end == text.c_str() + text.size();
}

bool parseNumber(const std::string& text, double& value)
{
    if (text.empty()) {
        return false;
    }
    char* end = nullptr;
    value = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size();
}

/// The same file, whether or not it exists yet.
bool samePath(const std::string& a, const std::string& b)
{
    std::error_code error;
    if (std::filesystem::exists(a, error) && std::filesystem::exists(b, error)) {
        return std::filesystem::equivalent(a, b, error);
    }
    return std::filesystem::weakly_canonical(std::filesystem::absolute(a), error) ==
           std::filesystem::weakly_canonical(std::filesystem::absolute(b), error);
}

} // namespace

CLI::Validator wholeNumberIn(long long low, long long high, const std::string& lowMeaning)
{
    const std::string range = "must be a whole number from " + std::to_string(low) + lowMeaning +
                              " to " + std::to_string(high);
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            long long value = 0;
            if (!parseWholeNumber(text, value) || value < low || value > high) {
                return range + ", got '" + text + "'";
            }
            return {};
        },
        "");
}

CLI::Validator seedNumber()
{
    return CLI::Validator(
        [](std::string& text) -> std::string {
            const bool digits = !text.empty() && text.size() <= 20 &&
                                std::all_of(text.begin(), text.end(),
                                            [](char c) { return c >= '0' && c <= '9'; });
            errno = 0;
            if (digits) {
                (void)std::strtoull(text.c_str(), nullptr, 10);
            }
            if (!digits || errno == ERANGE) {
                return "must be a whole number from 0 to 18446744073709551615, got '" + text +
                       "'";
            }
            return {};
        },
        "");
}

CLI::Validator positiveNumber()
{
    return CLI::Validator(
        [](std::string& text) -> std::string {
            double value = 0.0;
            if (!parseNumber(text, value) || !std::isfinite(value) || !(value > 0.0)) {
                return "must be a number above 0, got '" + text + "'";
            }
            return {};
        },
        "");
}

CLI::Validator nonNegativeNumber()
{
    return CLI::Validator(
        [](std::string& text) -> std::string {
            double value = 0.0;
            if (!parseNumber(text, value) || !std::isfinite(value) || value < 0.0) {
                return "must be a number at or above 0, got '" + text + "'";
            }
            return {};
        },
        "");
}

CLI::Option* addThreadsOption(CLI::App* command, int& threads, const std::string& what)
{
    return command->add_option("--threads", threads, what)
        ->type_name("K")
        ->check(wholeNumberIn(0, kMaxThreads, " (one per core)"));
}

int resolvedThreadCount(int threads)
{
    if (threads > 0) {
        return std::min(threads, kMaxThreads);
    }
    const auto cores = static_cast<int>(std::thread::hardware_concurrency());
    return std::clamp(cores, 1, kMaxThreads);
}

void checkDistinctPaths(const std::string& inputPath,
                        const std::vector<std::pair<std::string, std::string>>& outputs)
{
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const auto& [option, path] = outputs[i];
        // "-" is stdout; a device or pipe (/dev/null) may take several outputs
        std::error_code error;
        const auto status = std::filesystem::status(path, error);
        if (path.empty() || path == "-" ||
            (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))) {
            continue;
        }
        if (!inputPath.empty() && samePath(path, inputPath)) {
            throw UsageError(option, path + " is the scenario file being read; choose another "
                                            "path");
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (!outputs[j].second.empty() && outputs[j].second != "-" &&
                samePath(path, outputs[j].second)) {
                throw UsageError(option, path + " is also the path of " + outputs[j].first +
                                             "; give each output its own file");
            }
        }
    }
}

std::string oneLineParseMessage(const CLI::ParseError& error)
{
    std::string message;
    for (const char c : std::string(error.what())) {
        message += (c == '\n' || c == '\r') ? ' ' : c;
    }
    return message;
}

int reportParseError(const CLI::App& app, const CLI::ParseError& error, int argc, char** argv)
{
    const std::string first = argc >= 2 ? argv[1] : "";
    if (first == "help") {
        std::cout << app.help();
        return kExitOk;
    }
    std::string commands;
    for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; })) {
        commands += (commands.empty() ? "" : ", ") + command->get_name();
    }
    std::string message;
    const bool commandParsed = !app.get_subcommands().empty();
    if (!commandParsed && first.empty()) {
        message = "a command is required (" + commands + "; tumble --help)";
    } else if (!commandParsed && !first.starts_with("-")) {
        message = "unknown command '" + first + "' (commands: " + commands + "; tumble --help)";
    } else {
        message = oneLineParseMessage(error);
        if (commandParsed) {
            message += " (tumble " + app.get_subcommands().front()->get_name() + " --help)";
        }
    }
    printError(message);
    return kExitBadInput;
}

} // namespace tumble::cli
