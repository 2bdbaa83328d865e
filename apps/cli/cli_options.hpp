// Options shared by several commands and the one convention for command-line errors: one line
// "tumble: error: OPTION: problem" on stderr, exit code 2.
#pragma once

#include <CLI/CLI.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace tumble::cli {

/// The most threads any command accepts: above it OpenMP aborts or crawls (issue 14, item 4).
constexpr int kMaxThreads = 256;

/// A bad command line found after parsing (clashing paths, an out-of-range value): exit code 2.
class UsageError : public std::runtime_error {
public:
    /// what() is "OPTION: problem".
    UsageError(const std::string& option, const std::string& problem)
        : std::runtime_error(option + ": " + problem)
    {
    }
};

/// Whole numbers from `low` to `high`, with the range in plain numbers in the message.
CLI::Validator wholeNumberIn(long long low, long long high, const std::string& lowMeaning = "");

/// A seed: a whole number from 0 to 2^64 - 1, written in decimal digits (no sign).
CLI::Validator seedNumber();

/// A finite number above zero.
CLI::Validator positiveNumber();

/// A finite number at or above zero.
CLI::Validator nonNegativeNumber();

/// --threads K on `command`: 0 (the default, one thread per core) up to kMaxThreads.
CLI::Option* addThreadsOption(CLI::App* command, int& threads, const std::string& what);

/// The thread count `threads` (0: one per core) stands for, at most kMaxThreads.
int resolvedThreadCount(int threads);

/// Rejects outputs that would overwrite the input or each other (issue 14, item 11): each pair is
/// (option, path); empty paths and "-" are skipped. Throws UsageError.
void checkDistinctPaths(const std::string& inputPath,
                        const std::vector<std::pair<std::string, std::string>>& outputs);

/// CLI11's message for a failed parse as one line ("--threads: must be ..."): no line breaks,
/// and numbers too long to read shortened.
std::string oneLineParseMessage(const CLI::ParseError& error);

/// Reports a failed parse as one line "tumble: error: ..." (an unknown command named as such,
/// with the list of commands) and returns exit code 2; `tumble help` prints the help, exit 0.
int reportParseError(const CLI::App& app, const CLI::ParseError& error, int argc, char** argv);

} // namespace tumble::cli
