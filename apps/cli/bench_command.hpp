// `tumble bench`: time the benchmark scenarios (S1, the handout drop; S4, N tumbling cuboids; the
// contact scenes S5, a stack of 20 and Jolt's pyramid) in tumble and, with --peers, in Bullet, ODE
// and MuJoCo on the same bodies, and print their tables; then the throughput of `tumble throw` on
// the shipped die.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace tumble::cli {

struct BenchOptions {
    /// Scenes to time, of S1, S4, S5 (pile_100.toml), stack20 (stack_20.toml) and pyramid
    /// (pyramid_1240.toml); S5 and the pyramid take one to two minutes a row, so not by default.
    std::vector<std::string> scenes{"S1", "S4", "stack20"};
    /// Body counts of S4.
    std::vector<int> bodies{100, 1000, 4000};
    /// Thread counts tumble is timed with (0: one per core).
    std::vector<int> threads{1, 2};
    /// Simulated time of every scenario, s; 0 (the default) keeps each file's own.
    double duration = 0.0;
    /// Throws of the dice scenario (dice_cube.toml) timed at each thread count; 0 skips it.
    long throws = 10000;
    /// Also run the peer engines compiled in (TUMBLE_BUILD_PEERS).
    bool peers = false;
    /// "KEY=VALUE" overrides every scenario of the run gets (--set), after --duration's, so they
    /// win: world.solver_iterations=10 times tumble at a peer's sweep budget.
    std::vector<std::string> overrides;
    /// Folder holding part3_task4_friction.toml (S1), s4_tumbling_cuboids.toml (S4),
    /// pile_100.toml (S5), stack_20.toml and dice_cube.toml (the dice throughput).
    std::string scenarioDir;
    /// Folder holding pyramid_1240.toml, the scenes too slow for scenarios/ (bench/scenes).
    std::string benchSceneDir;
};

/// Declares the `bench` subcommand on `app`, filling `options` when parsed.
CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options);

/// Runs the benchmark and prints the table; returns the process exit code.
int benchCommand(const BenchOptions& options);

} // namespace tumble::cli
