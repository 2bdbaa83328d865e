// The viewer's entry point, called by `tumble view`: options in, exit code out.
#pragma once

#include "tumble/scenario/runner.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace tumble::viewer {

/// How the log panel words what happens, supplied by the program (the CLI passes its console
/// printer, so the panel shows exactly the lines `tumble run` prints). Either may be empty.
struct LogFormat {
    /// Printed when a run starts (scenario, dt, models, each body's inverse inertia).
    std::function<std::string(const scenario::Runner&)> header;
    /// The events of one step (impulses, collisions, rest).
    std::function<std::string(const scenario::Runner&, const scenario::StepReport&)> step;
};

/// Where the capture mode's image goes: the program opens and finishes the file, so its checks
/// and errors are the program's own.
struct ScreenshotTarget {
    /// The image's name in messages.
    std::filesystem::path path;
    /// Stores the whole PNG file; throws when it cannot.
    std::function<void(std::span<const std::uint8_t>)> write;
};

struct ViewerOptions {
    /// Scenario file; empty for the default (scenarios/part3_task4_friction.toml).
    std::filesystem::path file;
    /// "KEY=VALUE" overrides, as `tumble run --set` takes them.
    std::vector<std::string> overrides;
    /// Capture mode: render one frame at time `at` as PNG into this target and exit.
    std::optional<ScreenshotTarget> screenshot;
    /// Simulated time to start at, s (the window opens paused there).
    std::optional<double> at;
    /// Window or image size, pixels.
    int width = 1280;
    int height = 720;
    /// Draw the ImGui panels.
    bool showUi = true;
    LogFormat log;
};

/// Opens the viewer on a scenario, or in capture mode writes one frame and prints how long it
/// took to render. Returns the exit code. Throws ScenarioError for a bad scenario,
/// std::runtime_error when no window or GL context can be made, and what the screenshot target's
/// write throws.
int runViewer(const ViewerOptions& options);

} // namespace tumble::viewer
