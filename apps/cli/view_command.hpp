// `tumble view`: open the viewer on a scenario, or capture one frame of it into a PNG file.
// Built without the viewer (-DTUMBLE_BUILD_VIEWER=OFF), the command says so and exits with 2.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace tumble::cli {

struct ViewOptions {
    /// Scenario file; empty for the default (part 3, task 4).
    std::string file;
    /// Capture mode: the PNG to write; empty for the interactive viewer.
    std::string screenshot;
    /// Simulated time to capture (or to open paused at), s; empty for 0.
    std::string at;
    /// Window or image size, "WxH".
    std::string size = "1280x720";
    /// Leave the panels out (the 3D view alone).
    bool noUi = false;
    /// "KEY=VALUE" overrides, in command-line order.
    std::vector<std::string> overrides;
    /// --throw I: play throw I of a [throw] scenario (as --replay writes it); negative for none.
    std::int64_t throwIndex = -1;
    /// The seed of --throw's draws.
    std::uint64_t seed = 1;
};

/// Declares the `view` subcommand on `app`, filling `options` when parsed.
CLI::App* addViewCommand(CLI::App& app, ViewOptions& options);

/// Runs the viewer; returns the process exit code. Throws ScenarioError for a bad scenario.
int viewCommand(const ViewOptions& options);

} // namespace tumble::cli
