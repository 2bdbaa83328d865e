// The log panel: the same console lines `tumble run` prints (inverse inertia, impulses,
// collisions with their vertices and average, rest), following the newest line.
#include "viewer/ui/panels.hpp"

#include <imgui.h>

namespace tumble::viewer::ui {

void drawLog(ViewerState& state)
{
    if (ImGui::SmallButton("clear")) {
        state.log.clear();
    }
    ImGui::SameLine();
    ImGui::TextDisabled("%zu lines", state.log.lines().size());

    ImGui::BeginChild("lines", ImVec2(0.0f, 0.0f), false, ImGuiWindowFlags_HorizontalScrollbar);
    // stay at the bottom while new lines arrive, unless the user has scrolled up
    const bool atBottom = ImGui::GetScrollY() >= ImGui::GetScrollMaxY() - 1.0f;
    const auto& lines = state.log.lines();
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(lines.size()));
    while (clipper.Step()) {
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            ImGui::TextUnformatted(lines[static_cast<std::size_t>(i)].c_str());
        }
    }
    clipper.End();
    if (atBottom) {
        ImGui::SetScrollHereY(1.0f);
    }
    ImGui::EndChild();
}

} // namespace tumble::viewer::ui
