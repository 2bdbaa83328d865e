// ViewerState: what the panels and keys work on (the simulation, the settings, the camera, the
// plots and the log), and the requests they leave for the loop to carry out after the frame.
#pragma once

#include "viewer/camera.hpp"
#include "viewer/impulse_experiments.hpp"
#include "viewer/log_buffer.hpp"
#include "viewer/plot_history.hpp"
#include "viewer/scenario_catalog.hpp"
#include "viewer/sim_runner.hpp"
#include "viewer/viewer_settings.hpp"

#include <filesystem>
#include <optional>
#include <vector>

namespace tumble::viewer {

struct ViewerState {
    SimRunner& sim;
    ViewerSettings& settings;
    OrbitCamera& camera;
    PlotHistory& plots;
    LogBuffer& log;
    const std::vector<ScenarioEntry>& catalog;
    const std::vector<ImpulseExperiment>& experiments;
    /// Real duration of the last frame, s.
    double frameSeconds = 0.0;

    /// Open this scenario file after the frame.
    std::optional<std::filesystem::path> openRequest;
    /// Put the camera back to the scenario's default view.
    bool resetViewRequest = false;
    bool quitRequest = false;
};

} // namespace tumble::viewer
