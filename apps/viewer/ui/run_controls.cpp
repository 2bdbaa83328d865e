// The run controls panel: play/pause (space), single step (N), reset (R), the time scale, the
// simulated time, and the last error.
#include "viewer/ui/panels.hpp"

#include <imgui.h>

#include <cstdio>

namespace tumble::viewer::ui {
namespace {

const ImVec4 kErrorColour{1.0f, 0.45f, 0.4f, 1.0f};
const ImVec4 kWarningColour{1.0f, 0.8f, 0.3f, 1.0f};

} // namespace

void drawRunControls(ViewerState& state)
{
    SimRunner& sim = state.sim;
    const Real dt = sim.runner().scenario().dt;
    ImGui::Text("t = %.4f s  (%lld steps of %.4g s)", sim.time(), sim.runner().stepCount(), dt);

    if (ImGui::Button(sim.paused() ? "Play (space)" : "Pause (space)")) {
        sim.togglePaused();
    }
    ImGui::SameLine();
    if (ImGui::Button("Step (N)")) {
        sim.stepOnce();
    }
    ImGui::SameLine();
    if (ImGui::Button("Reset (R)")) {
        sim.reset();
    }

    // slow motion down to 0.1x, fast forward up to 2x
    auto scale = static_cast<float>(sim.timeScale());
    if (ImGui::SliderFloat("time scale", &scale, static_cast<float>(SimRunner::kMinTimeScale),
                           static_cast<float>(SimRunner::kMaxTimeScale), "%.2fx",
                           ImGuiSliderFlags_Logarithmic)) {
        sim.setTimeScale(scale);
    }
    for (const float preset : {0.1f, 0.25f, 0.5f, 1.0f, 2.0f}) {
        char label[16];
        std::snprintf(label, sizeof label, "%gx", static_cast<double>(preset));
        if (ImGui::SmallButton(label)) {
            sim.setTimeScale(preset);
        }
        ImGui::SameLine();
    }
    ImGui::NewLine();

    // real frame time (none in the capture mode, which draws a single moment)
    if (state.frameSeconds > 0.0) {
        const double frameMs = 1000.0 * state.frameSeconds;
        ImGui::TextDisabled("frame %.1f ms (%.0f fps)", frameMs, 1000.0 / frameMs);
    }
    if (sim.fellBehind()) {
        ImGui::SameLine();
        ImGui::TextColored(kWarningColour, "behind real time");
    }
    if (!sim.error().empty()) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(kErrorColour, "%s", sim.error().c_str());
        ImGui::PopTextWrapPos();
        if (ImGui::SmallButton("dismiss")) {
            sim.clearError();
        }
    }
}

} // namespace tumble::viewer::ui
