#include "view_command.hpp"

#include "cli_options.hpp"
#include "console.hpp"
#include "output_file.hpp"
#include "view_throw.hpp"

#include "tumble/scenario/runner.hpp"

#if TUMBLE_HAS_VIEWER
#include "viewer/viewer.hpp"
#endif

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

namespace tumble::cli {
namespace {

/// Accepted image and window sizes, pixels per side.
constexpr int kMinSide = 16;
constexpr int kMaxSide = 8192;

/// "WxH" to a width and height within the accepted sizes.
std::optional<std::pair<int, int>> parseSize(const std::string& text)
{
    int width = 0;
    int height = 0;
    char rest = 0;
    if (std::sscanf(text.c_str(), "%dx%d%c", &width, &height, &rest) != 2 || width < kMinSide ||
        height < kMinSide || width > kMaxSide || height > kMaxSide) {
        return std::nullopt;
    }
    return std::make_pair(width, height);
}

/// The most steps --at may ask for: run's limit on duration / dt (docs/scenario-format.md).
constexpr Real kMostSteps = 1e9;

/// --at within run's limits for the scenario's dt, or exit 2 (issue 14, item 8): 1e20 and nan
/// used to capture t = 0, and 1e12 ran until killed.
void checkCaptureTime(const ViewOptions& options)
{
    const Real at = std::strtod(options.at.c_str(), nullptr);
    const std::string file = options.file.empty()
                                 ? std::string(TUMBLE_SCENARIO_DIR) + "/part3_task4_friction.toml"
                                 : options.file;
    const scenario::Scenario loaded = scenario::loadScenario(file, options.overrides);
    if (at / loaded.dt > kMostSteps) {
        char steps[32];
        std::snprintf(steps, sizeof steps, "%.3g", at / loaded.dt);
        throw UsageError("--at", "the number of steps --at / dt must be at most 1e+09, got " +
                                     std::string(steps) + " (dt = " + formatFull(loaded.dt) +
                                     " s)");
    }
}

/// The capture mode writes PNG only: any other name is exit 2, so no .jpg holds PNG data.
void checkImageName(const std::string& path)
{
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".png") {
        throw UsageError("--screenshot", "the capture is a PNG image, so the file name must end "
                                         "in .png, got \"" + path + "\"");
    }
}

#if TUMBLE_HAS_VIEWER
/// The log panel gets the console lines `tumble run` prints.
viewer::LogFormat consoleFormat()
{
    return {
        .header =
            [](const scenario::Runner& runner) {
                const scenario::Scenario& scenario = runner.scenario();
                const auto steps =
                    static_cast<long long>(std::ceil(scenario.duration / scenario.dt - 1e-6));
                std::ostringstream out;
                Console(out, false).printHeader(runner, steps);
                return out.str();
            },
        .step =
            [](const scenario::Runner& runner, const scenario::StepReport& report) {
                std::ostringstream out;
                Console(out, false).printStep(runner, report);
                return out.str();
            },
    };
}
#endif

} // namespace

CLI::App* addViewCommand(CLI::App& app, ViewOptions& options)
{
    CLI::App* command =
        app.add_subcommand("view", "Watch a scenario in a window, or capture a frame as PNG");
    command->add_option("FILE", options.file,
                        "Scenario file (TOML); default scenarios/part3_task4_friction.toml")
        ->type_name("");
    command->add_option("--screenshot", options.screenshot,
                        "Render one frame at --at into this PNG file and exit")
        ->type_name("OUT.png");
    command->add_option("--at", options.at, "Simulated time to capture, or to open paused at, s (default 0)")
        ->type_name("T")
        ->check(nonNegativeNumber());
    command->add_option("--size", options.size, "Window or image size (default 1280x720)")
        ->type_name("WxH");
    command->add_flag("--no-ui", options.noUi, "Draw the 3D view without the panels");
    command->add_option("--set", options.overrides,
                        "Override a scenario value, KEY=VALUE (as for run); repeatable")
        ->type_name("KEY=VALUE")
        ->allow_extra_args(false);
    command->add_option("--throw", options.throwIndex,
                        "Play throw I of the file's [throw] table (all its dice)")
        ->type_name("I")
        ->check(wholeNumberIn(0, std::numeric_limits<std::int64_t>::max()));
    command->add_option("--seed", options.seed, "Seed of --throw's draws (default 1)")
        ->type_name("S")
        ->check(seedNumber());
    return command;
}

int viewCommand(const ViewOptions& given)
{
    // --throw: the viewer plays the throw's replay file, as `tumble throw --replay` writes it
    const ThrowViewFile throwFile(given);
    const ViewOptions& options = throwFile.options();
    const auto size = parseSize(options.size);
    if (!size) {
        printError("--size: expected WxH with each side from " + std::to_string(kMinSide) +
                   " to " + std::to_string(kMaxSide) + " pixels, got \"" + options.size + "\"");
        return kExitBadInput;
    }
    if (!options.screenshot.empty()) {
        checkImageName(options.screenshot);
    }
    if (!options.at.empty()) {
        checkCaptureTime(options);
    }
#if TUMBLE_HAS_VIEWER
    viewer::ViewerOptions viewerOptions;
    viewerOptions.file = options.file;
    viewerOptions.overrides = options.overrides;
    // the image is opened before any window, as run opens its CSV files: an output that cannot
    // be written is exit 3 with the system's reason, and the file is whole or not there
    std::optional<OutputFile> image;
    if (!options.screenshot.empty()) {
        image.emplace(options.screenshot);
        viewerOptions.screenshot = viewer::ScreenshotTarget{
            .path = options.screenshot,
            .write = [&image](std::span<const std::uint8_t> bytes) {
                std::fwrite(bytes.data(), 1, bytes.size(), image->handle());
                image->finish();
            }};
    }
    if (!options.at.empty()) {
        viewerOptions.at = std::stod(options.at);
    }
    viewerOptions.width = size->first;
    viewerOptions.height = size->second;
    viewerOptions.showUi = !options.noUi;
    viewerOptions.log = consoleFormat();
    return viewer::runViewer(viewerOptions);
#else
    printError("this tumble was built without the viewer; install its packages "
               "(bash tools/install-deps.sh) and configure with -DTUMBLE_BUILD_VIEWER=ON");
    return kExitBadInput;
#endif
}

} // namespace tumble::cli
