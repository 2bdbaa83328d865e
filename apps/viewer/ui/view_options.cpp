// The view options panel: which overlays to draw, arrow scales, and the camera's follow mode.
#include "viewer/ui/panels.hpp"

#include <imgui.h>

namespace tumble::viewer::ui {

void drawViewOptions(ViewerState& state)
{
    ViewerSettings& settings = state.settings;
    ImGui::Checkbox("follow the body (F)", &settings.followBody);
    ImGui::SameLine();
    if (ImGui::Button("reset view (V)")) {
        state.resetViewRequest = true;
    }
    ImGui::Checkbox("body axes (X)", &settings.showAxes);
    ImGui::Checkbox("angular velocity w", &settings.showAngularVelocity);
    ImGui::SameLine();
    ImGui::Checkbox("angular momentum L", &settings.showAngularMomentum);
    ImGui::Checkbox("contact vertices", &settings.showContacts);
    ImGui::SameLine();
    ImGui::Checkbox("collision impulses", &settings.showImpulses);
    ImGui::Checkbox("shadow", &settings.showShadow);
    ImGui::PushItemWidth(-150.0f);
    ImGui::SliderFloat("impulse arrows, m/(N s)", &settings.impulseScale, 0.01f, 1.0f, "%.3f",
                       ImGuiSliderFlags_Logarithmic);
    ImGui::SliderFloat("w, L arrows, m per unit", &settings.vectorScale, 0.05f, 5.0f, "%.2f",
                       ImGuiSliderFlags_Logarithmic);
    ImGui::PopItemWidth();
    ImGui::TextDisabled("drag: orbit  right/middle drag: pan  wheel: zoom");
}

} // namespace tumble::viewer::ui
