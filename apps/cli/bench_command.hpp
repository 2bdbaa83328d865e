// `tumble bench`: time the benchmark scenarios (S1, the handout drop; S4, N tumbling cuboids) in
// tumble and, with --peers, in Bullet, ODE and MuJoCo on the same bodies, and print one table;
// then the throughput of `tumble throw` on the shipped die.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace tumble::cli {

struct BenchOptions {
    /// Body counts of S4.
    std::vector<int> bodies{100, 1000, 4000};
    /// Thread counts tumble is timed with (0: one per core).
    std::vector<int> threads{1, 2};
    /// Simulated time of every scenario, s.
    double duration = 10.0;
    /// Throws of the dice scenario (dice_cube.toml) timed at each thread count; 0 skips it.
    long throws = 10000;
    /// Also run the peer engines compiled in (TUMBLE_BUILD_PEERS).
    bool peers = false;
    /// Folder holding part3_task4_friction.toml (S1), s4_tumbling_cuboids.toml (S4) and
    /// dice_cube.toml (the dice throughput).
    std::string scenarioDir;
};

/// Declares the `bench` subcommand on `app`, filling `options` when parsed.
CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options);

/// Runs the benchmark and prints the table; returns the process exit code.
int benchCommand(const BenchOptions& options);

} // namespace tumble::cli
