// The viewer's main: makes the window, renderer, simulation, camera and panels, wires them
// together, and runs either the interactive loop or the capture mode.
#include "viewer/viewer.hpp"

#include "viewer/camera.hpp"
#include "viewer/capture.hpp"
#include "viewer/impulse_experiments.hpp"
#include "viewer/input.hpp"
#include "viewer/log_buffer.hpp"
#include "viewer/picking.hpp"
#include "viewer/plot_history.hpp"
#include "viewer/renderer/renderer.hpp"
#include "viewer/scenario_catalog.hpp"
#include "viewer/scene_bounds.hpp"
#include "viewer/scene_builder.hpp"
#include "viewer/sim_runner.hpp"
#include "viewer/ui/layout.hpp"
#include "viewer/ui/panels.hpp"
#include "viewer/viewer_settings.hpp"
#include "viewer/viewer_state.hpp"
#include "viewer/window.hpp"

#include <glm/glm.hpp>
#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace tumble::viewer {
namespace {

/// The plots show this many seconds, sampled this often.
constexpr double kPlotWindowSeconds = 10.0;
constexpr double kPlotSampleSeconds = 1.0 / 120.0;

/// The 3D view's part of the window: what the panels leave free.
ViewRegion sceneRegion(const ViewerSettings& settings, const glm::ivec2& size)
{
    return settings.showUi ? ui::freeViewRegion(glm::vec2(size)) : wholeView(size);
}

OrbitCamera defaultCamera(const SimRunner& sim, const ViewerSettings& settings,
                          const glm::ivec2& display)
{
    const glm::vec2 region = sceneRegion(settings, display).size();
    return frameBounds(runBounds(sim.scenario()), region.x / std::max(region.y, 1.0f));
}

PlotSample sampleOf(const SimRunner& sim, std::size_t index)
{
    const Body& body = sim.body(index);
    const Real kinetic = body.kineticEnergy();
    const Real potential = body.potentialEnergy(sim.world().settings().gravity);
    return {.time = static_cast<float>(sim.time()),
            .height = static_cast<float>(body.position.y),
            .speed = static_cast<float>(glm::length(body.linearVelocity)),
            .angularSpeed = static_cast<float>(glm::length(body.angularVelocity)),
            .kinetic = static_cast<float>(kinetic),
            .potential = static_cast<float>(potential),
            .total = static_cast<float>(kinetic + potential)};
}

/// The log and the plots follow every run start and every step.
void wireListeners(ViewerState& state, const LogFormat& format)
{
    state.sim.setResetListener([&state, format](const scenario::Runner& runner) {
        state.plots.clear();
        if (state.settings.selectedBody >= runner.bodies().size()) {
            state.settings.selectedBody = 0;
        }
        if (format.header) {
            state.log.append(format.header(runner));
        }
        if (!runner.bodies().empty()) {
            state.plots.record(sampleOf(state.sim, state.settings.selectedBody));
        }
    });
    state.sim.setStepListener(
        [&state, format](const scenario::Runner& runner, const scenario::StepReport& report) {
            if (format.step) {
                state.log.append(format.step(runner, report));
            }
            if (runner.bodies().empty()) {
                return;
            }
            const BodyId selected = runner.bodies()[state.settings.selectedBody];
            for (const CollisionEvent& collision : report.collisions) {
                if (collision.manifold.body == selected) {
                    state.plots.markCollision(static_cast<float>(collision.time));
                }
            }
            state.plots.record(sampleOf(state.sim, state.settings.selectedBody));
        });
}

/// The scene in the part of the window the panels leave it (display is the window's size in
/// ImGui's units, framebuffer its size in pixels; they differ on high-density screens).
void drawScene(const ViewerState& state, Renderer& renderer, const glm::ivec2& display,
               const glm::ivec2& framebuffer)
{
    const SimRunner& sim = state.sim;
    const SceneDrawList scene =
        buildScene(sim.world(), sim.runner().bodies(), sim.lastCollisions(), state.settings,
                   referenceGridHeight(sim.scenario()));
    const glm::vec2 scale = glm::vec2(framebuffer) / glm::max(glm::vec2(display), glm::vec2(1.0f));
    const ViewRegion region = sceneRegion(state.settings, display);
    renderer.draw(scene, state.camera, {region.min * scale, region.max * scale}, framebuffer,
                  state.settings.showShadow);
}

/// Opens a requested scenario and resets the view when asked.
void applyRequests(ViewerState& state, const glm::ivec2& size)
{
    if (state.openRequest) {
        if (state.sim.open(*state.openRequest)) {
            state.camera = defaultCamera(state.sim, state.settings, size);
        }
        state.openRequest.reset();
    }
    if (state.resetViewRequest) {
        state.camera = defaultCamera(state.sim, state.settings, size);
        state.resetViewRequest = false;
    }
}

/// A click (a press and release without dragging) in the 3D view selects the moving body under
/// the pointer for the inspector and the plots.
void pickWithMouse(ViewerState& state, const ViewRegion& region)
{
    const ImGuiIO& io = ImGui::GetIO();
    constexpr float kClickSlopSquared = 9.0f;
    if (io.WantCaptureMouse || !ImGui::IsMouseReleased(ImGuiMouseButton_Left) ||
        io.MouseDragMaxDistanceSqr[ImGuiMouseButton_Left] > kClickSlopSquared) {
        return;
    }
    const glm::vec2 pixel = glm::vec2(io.MousePos.x, io.MousePos.y) - region.min;
    if (pixel.x < 0.0f || pixel.y < 0.0f || pixel.x > region.size().x ||
        pixel.y > region.size().y) {
        return;
    }
    const std::optional<std::size_t> picked =
        pickBody(pixelRay(state.camera, pixel, region.size()), state.sim.world(),
                 state.sim.runner().bodies());
    if (picked) {
        state.settings.selectedBody = *picked;
    }
}

void runLoop(Window& window, Renderer& renderer, ViewerState& state)
{
    double last = window.time();
    while (!window.shouldClose() && !state.quitRequest) {
        window.pollEvents();
        const double now = window.time();
        state.frameSeconds = now - last;
        last = now;
        const glm::ivec2 size = window.framebufferSize();

        // input, then the fixed steps this frame's real time made due, then the panels
        window.beginUiFrame();
        const glm::ivec2 display(ImGui::GetIO().DisplaySize.x, ImGui::GetIO().DisplaySize.y);
        const ViewRegion region = sceneRegion(state.settings, display);
        handleMouse(state.camera, region.size().y);
        pickWithMouse(state, region);
        handleKeys(state, window.takeKeyPresses());
        state.sim.advance(state.frameSeconds);
        if (state.settings.followBody && state.sim.bodyCount() > 0) {
            state.camera.follow(glm::vec3(state.sim.body(state.settings.selectedBody).position),
                                static_cast<float>(state.frameSeconds));
        }
        if (state.settings.showUi) {
            ui::drawPanels(state);
        }
        applyRequests(state, display);

        drawScene(state, renderer, display, size);
        window.renderUi();
        window.swapBuffers();
    }
}

int capture(Window& window, Renderer& renderer, ViewerState& state,
            const ScreenshotTarget& screenshot, const glm::ivec2& size)
{
    const std::filesystem::path& png = screenshot.path;
    const CaptureTiming timing = captureFrame(screenshot.write, size.x, size.y, [&] {
        window.beginUiFrame(size);
        if (state.settings.showUi) {
            ui::drawPanels(state);
        }
        drawScene(state, renderer, size, size);
        window.renderUi();
    });
    std::printf("wrote %s (%dx%d) at t = %.6f s\n", png.string().c_str(), size.x, size.y,
                state.sim.time());
    std::printf("frame render time: %.2f ms (median of %d frames; the first took %.1f ms; "
                "%.2f ms of processor time per frame), renderer: %s\n",
                timing.medianFrameMs, timing.timedFrames, timing.firstFrameMs, timing.cpuFrameMs,
                timing.renderer.c_str());
    if (!state.sim.error().empty()) {
        std::fprintf(stderr, "tumble: warning: %s\n", state.sim.error().c_str());
    }
    return 0;
}

} // namespace

int runViewer(const ViewerOptions& options)
{
    // the scenario first, so a bad file is reported before any window opens
    const std::filesystem::path scenarioDirectory =
        findScenarioDirectory(TUMBLE_VIEWER_SCENARIO_DIR);
    const std::filesystem::path file =
        options.file.empty() ? scenarioDirectory / kDefaultScenarioFile : options.file;
    SimRunner sim(file, options.overrides);
    const std::filesystem::path folder =
        file.has_parent_path() ? file.parent_path() : std::filesystem::path(".");
    const std::vector<ScenarioEntry> catalog = listScenarios(folder);
    std::vector<ImpulseExperiment> experiments = loadImpulseExperiments(folder);
    if (experiments.empty()) {
        experiments = loadImpulseExperiments(scenarioDirectory);
    }

    const glm::ivec2 size(options.width, options.height);
    Window window({.width = size.x, .height = size.y, .visible = !options.screenshot});
    Renderer renderer;
    ViewerSettings settings{.showUi = options.showUi};
    OrbitCamera camera = defaultCamera(sim, settings, size);
    PlotHistory plots(kPlotWindowSeconds, kPlotSampleSeconds);
    LogBuffer log;
    ViewerState state{.sim = sim,
                      .settings = settings,
                      .camera = camera,
                      .plots = plots,
                      .log = log,
                      .catalog = catalog,
                      .experiments = experiments};
    wireListeners(state, options.log);

    if (options.at) {
        sim.advanceTo(*options.at);
    }
    if (options.screenshot) {
        return capture(window, renderer, state, *options.screenshot, size);
    }
    sim.setPaused(options.at.has_value());
    runLoop(window, renderer, state);
    return 0;
}

} // namespace tumble::viewer
