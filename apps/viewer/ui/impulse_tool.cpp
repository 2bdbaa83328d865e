// The impulse tool: an impulse at an offset applied now, or a target velocity and angular
// velocity that tumble solves for (one impulse at one point), and one button per impulse
// experiment of the handouts (part 2 task 2, part 3 task 1).
#include "viewer/ui/panels.hpp"

#include "tumble/impulse_target.hpp"

#include <imgui.h>

#include <cstdio>
#include <string>

namespace tumble::viewer::ui {
namespace {

std::string describeApplied(const ImpulseTarget& solved)
{
    char text[160];
    std::snprintf(text, sizeof text, "J = (%.3f, %.3f, %.3f) N s at r = (%.3f, %.3f, %.3f) m",
                  solved.impulse.x, solved.impulse.y, solved.impulse.z, solved.offset.x,
                  solved.offset.y, solved.offset.z);
    return text;
}

void solveAndApply(ViewerState& state, const Vec3& velocity, const std::optional<Vec3>& spin,
                   const std::string& label)
{
    const ImpulseTarget solved =
        state.sim.applyTarget(state.settings.selectedBody, velocity, spin, label);
    state.settings.impulseTool.lastResult =
        solved.status == ImpulseTargetStatus::Reached
            ? label + ": " + describeApplied(solved)
            : label + ": not reachable: " + describe(solved.status);
}

void drawExperiments(ViewerState& state)
{
    ImpulseToolInputs& inputs = state.settings.impulseTool;
    if (state.experiments.empty()) {
        ImGui::TextDisabled("the handout impulse scenarios were not found");
        return;
    }
    ImGui::Checkbox("start from the experiment's velocities", &inputs.startFromExperiment);
    for (const ImpulseExperiment& experiment : state.experiments) {
        if (ImGui::Button(experiment.label.c_str())) {
            if (inputs.startFromExperiment) {
                state.sim.setVelocities(state.settings.selectedBody, experiment.startVelocity,
                                        experiment.startAngularVelocity);
            }
            if (experiment.targetVelocity) {
                solveAndApply(state, *experiment.targetVelocity, experiment.targetAngularVelocity,
                              experiment.label);
            } else {
                state.sim.applyImpulse(state.settings.selectedBody, experiment.impulse,
                                       experiment.offset, experiment.label);
                inputs.lastResult = experiment.label + ": applied";
            }
        }
        if (ImGui::IsItemHovered() && experiment.targetVelocity) {
            const Vec3& v = *experiment.targetVelocity;
            const Vec3 w = experiment.targetAngularVelocity.value_or(Vec3(0.0));
            ImGui::SetTooltip("from v = (%g, %g, %g), w = (%g, %g, %g)\nto v = (%g, %g, %g), "
                              "w = (%g, %g, %g)",
                              experiment.startVelocity.x, experiment.startVelocity.y,
                              experiment.startVelocity.z, experiment.startAngularVelocity.x,
                              experiment.startAngularVelocity.y, experiment.startAngularVelocity.z,
                              v.x, v.y, v.z, w.x, w.y, w.z);
        }
    }
}

} // namespace

void drawImpulseTool(ViewerState& state)
{
    if (state.sim.bodyCount() == 0) {
        return;
    }
    ImpulseToolInputs& inputs = state.settings.impulseTool;
    drawBodySelector(state);
    ImGui::PushItemWidth(-120.0f);

    // an impulse given directly
    ImGui::InputFloat3("impulse, N s", &inputs.impulse.x, "%.3f");
    ImGui::InputFloat3("offset, m", &inputs.offset.x, "%.3f");
    if (ImGui::Button("apply impulse")) {
        state.sim.applyImpulse(state.settings.selectedBody, Vec3(inputs.impulse),
                               Vec3(inputs.offset), "impulse from the viewer");
        inputs.lastResult = "applied";
    }
    ImGui::Separator();

    // a target, solved for
    ImGui::InputFloat3("target v, m/s", &inputs.targetVelocity.x, "%.3f");
    ImGui::BeginDisabled(inputs.keepAngularVelocity);
    ImGui::InputFloat3("target w, rad/s", &inputs.targetAngularVelocity.x, "%.3f");
    ImGui::EndDisabled();
    ImGui::Checkbox("keep w", &inputs.keepAngularVelocity);
    ImGui::SameLine();
    if (ImGui::Button("solve and apply")) {
        const std::optional<Vec3> spin =
            inputs.keepAngularVelocity ? std::nullopt
                                       : std::optional<Vec3>(Vec3(inputs.targetAngularVelocity));
        solveAndApply(state, Vec3(inputs.targetVelocity), spin, "target from the viewer");
    }
    ImGui::PopItemWidth();
    ImGui::Separator();

    ImGui::TextUnformatted("handout impulse experiments");
    drawExperiments(state);
    if (!inputs.lastResult.empty()) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("%s", inputs.lastResult.c_str());
        ImGui::PopTextWrapPos();
    }
}

} // namespace tumble::viewer::ui
