// `tumble run`: load a scenario, step it for its duration, report events on the console and
// optionally write the states to CSV.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace tumble::cli {

struct RunOptions {
    std::string file;
    /// CSV output path; empty for none, "-" for stdout.
    std::string csvPath;
    /// Steps between CSV samples (>= 1).
    int every = 1;
    /// Energy ledger and contact ledger CSV paths; empty for none.
    std::string energyCsvPath;
    std::string contactsCsvPath;
    /// Shorthands for --set world.duration= and --set world.dt=; empty when not given.
    std::string duration;
    std::string dt;
    bool quiet = false;
    /// Print "state hash: <16 hex digits>" of the final state (tumble/state_hash.hpp).
    bool hash = false;
    /// "KEY=VALUE" overrides, in command-line order.
    std::vector<std::string> overrides;
    /// Threads the world steps its bodies on (WorldSettings::threads); 0: one per core.
    int threads = 0;
};

/// Declares the `run` subcommand on `app`, filling `options` when parsed.
CLI::App* addRunCommand(CLI::App& app, RunOptions& options);

/// Runs the scenario; returns the process exit code. Throws ScenarioError for a bad scenario.
int runCommand(const RunOptions& options);

} // namespace tumble::cli
