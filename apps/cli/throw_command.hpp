// `tumble throw`: throw a scenario's die many times from drawn initial states and report how
// often each face ends down; or write one throw as a scenario file (--replay).
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace tumble::cli {

struct ThrowOptions {
    std::string file;
    /// Number of throws (>= 1).
    std::int64_t throws = 1000;
    std::uint64_t seed = 1;
    /// Threads; 0 means every core.
    int threads = 0;
    /// Per-throw CSV and summary JSON paths; empty for none.
    std::string csvPath;
    std::string summaryJsonPath;
    /// Throw index to write as a scenario file with --out; negative for none.
    std::int64_t replay = -1;
    std::string outPath;
    /// "KEY=VALUE" overrides, in command-line order.
    std::vector<std::string> overrides;
};

/// Declares the `throw` subcommand on `app`, filling `options` when parsed.
CLI::App* addThrowCommand(CLI::App& app, ThrowOptions& options);

/// Runs the throws (or writes the replay); returns the process exit code. Throws ScenarioError
/// for a bad scenario or a scenario without [throw].
int throwCommand(const ThrowOptions& options);

} // namespace tumble::cli
