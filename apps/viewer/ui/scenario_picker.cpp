// The scenario picker: the files of scenarios/ (keys 1..9 open the first nine, the handout
// scenarios first) and reload from disk after editing the TOML.
#include "viewer/ui/panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace tumble::viewer::ui {

void drawScenarioPicker(ViewerState& state)
{
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", state.sim.file().string().c_str());
    ImGui::PopTextWrapPos();
    if (ImGui::Button("Reload from disk (L)")) {
        state.sim.reload();
    }
    ImGui::SameLine();
    ImGui::TextDisabled("edit the TOML, then reload");

    if (state.catalog.empty()) {
        ImGui::TextDisabled("no scenarios/ folder found");
        return;
    }
    const float rows = static_cast<float>(std::min<std::size_t>(state.catalog.size(), 10));
    if (ImGui::BeginListBox("##scenarios",
                            ImVec2(-1.0f, rows * ImGui::GetTextLineHeightWithSpacing() + 4.0f))) {
        for (std::size_t i = 0; i < state.catalog.size(); ++i) {
            const ScenarioEntry& entry = state.catalog[i];
            const std::string key = i < 9 ? std::to_string(i + 1) : " ";
            const std::string label = key + "  " + entry.name;
            const bool current = entry.path.filename() == state.sim.file().filename();
            if (ImGui::Selectable(label.c_str(), current)) {
                state.openRequest = entry.path;
            }
        }
        ImGui::EndListBox();
    }
}

} // namespace tumble::viewer::ui
