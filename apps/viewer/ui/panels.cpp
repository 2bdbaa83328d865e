#include "viewer/ui/panels.hpp"

#include "viewer/ui/layout.hpp"

#include <imgui.h>

namespace tumble::viewer::ui {

namespace {

/// Panels stay where the layout puts them: the 3D view is drawn only in what they leave free.
/// Their background is the renderer's clear colour, already there: filling it again would cost
/// a software renderer more than the whole 3D view.
constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                         ImGuiWindowFlags_NoCollapse |
                                         ImGuiWindowFlags_NoBackground;

void place(const ViewRegion& region)
{
    ImGui::SetNextWindowPos(ImVec2(region.min.x, region.min.y));
    ImGui::SetNextWindowSize(ImVec2(region.size().x, region.size().y));
}

} // namespace

void drawPanels(ViewerState& state)
{
    const glm::vec2 display(ImGui::GetIO().DisplaySize.x, ImGui::GetIO().DisplaySize.y);

    // left column: running the scenario and changing it
    place(leftColumn(display));
    if (ImGui::Begin("tumble", nullptr, kPanelFlags)) {
        if (ImGui::CollapsingHeader("Run", ImGuiTreeNodeFlags_DefaultOpen)) {
            drawRunControls(state);
        }
        if (ImGui::CollapsingHeader("Scenario", ImGuiTreeNodeFlags_DefaultOpen)) {
            drawScenarioPicker(state);
        }
        if (ImGui::CollapsingHeader("Parameters")) {
            drawParameters(state);
        }
        if (ImGui::CollapsingHeader("View")) {
            drawViewOptions(state);
        }
    }
    ImGui::End();

    // right column: looking at one body and poking it
    place(rightColumn(display));
    if (ImGui::Begin("body", nullptr, kPanelFlags)) {
        if (ImGui::CollapsingHeader("Inspector", ImGuiTreeNodeFlags_DefaultOpen)) {
            drawInspector(state);
        }
        if (ImGui::CollapsingHeader("Plots", ImGuiTreeNodeFlags_DefaultOpen)) {
            drawPlots(state);
        }
        if (ImGui::CollapsingHeader("Impulse tool")) {
            drawImpulseTool(state);
        }
    }
    ImGui::End();

    // bottom, between the columns: the console lines
    place(logRegion(display));
    if (ImGui::Begin("log", nullptr, kPanelFlags)) {
        drawLog(state);
    }
    ImGui::End();
}

} // namespace tumble::viewer::ui
