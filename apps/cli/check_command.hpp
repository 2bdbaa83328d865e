// `tumble check`: validate a scenario file (and its --set overrides) without writing anything.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace tumble::cli {

struct CheckOptions {
    std::string file;
    std::vector<std::string> overrides;
};

/// Declares the `check` subcommand on `app`, filling `options` when parsed.
CLI::App* addCheckCommand(CLI::App& app, CheckOptions& options);

/// Prints "FILE: ok (...)" and returns the exit code. Throws ScenarioError for a bad scenario.
int checkCommand(const CheckOptions& options);

} // namespace tumble::cli
