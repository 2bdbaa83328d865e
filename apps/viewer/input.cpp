#include "viewer/input.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

namespace tumble::viewer {

void handleMouse(OrbitCamera& camera, float viewportHeight)
{
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse) {
        return;
    }
    // a button held since an earlier frame: the frame it went down, the pointer may have jumped
    const auto held = [&](ImGuiMouseButton button) {
        return io.MouseDown[button] && io.MouseDownDuration[button] > 0.0f;
    };
    if (held(ImGuiMouseButton_Left)) {
        camera.orbit(io.MouseDelta.x, io.MouseDelta.y);
    }
    if (held(ImGuiMouseButton_Right) || held(ImGuiMouseButton_Middle)) {
        camera.pan(io.MouseDelta.x, io.MouseDelta.y, viewportHeight);
    }
    if (io.MouseWheel != 0.0f) {
        camera.zoom(io.MouseWheel);
    }
}

void handleKeys(ViewerState& state, std::span<const KeyPress> presses)
{
    if (ImGui::GetIO().WantTextInput) {
        return;
    }
    for (const KeyPress& press : presses) {
        // only the single step repeats while its key is held
        if (press.repeat && press.key != GLFW_KEY_N) {
            continue;
        }
        switch (press.key) {
        case GLFW_KEY_SPACE:
            state.sim.togglePaused();
            break;
        case GLFW_KEY_N:
            state.sim.stepOnce();
            break;
        case GLFW_KEY_R:
            state.sim.reset();
            break;
        case GLFW_KEY_L:
            state.sim.reload();
            break;
        case GLFW_KEY_F:
            state.settings.followBody = !state.settings.followBody;
            break;
        case GLFW_KEY_V:
            state.resetViewRequest = true;
            break;
        case GLFW_KEY_X:
            state.settings.showAxes = !state.settings.showAxes;
            break;
        case GLFW_KEY_H:
            state.settings.showUi = !state.settings.showUi;
            break;
        case GLFW_KEY_ESCAPE:
            state.quitRequest = true;
            break;
        default:
            // 1..9 open the scenarios in the picker's order
            if (press.key >= GLFW_KEY_1 && press.key <= GLFW_KEY_9) {
                const auto index = static_cast<std::size_t>(press.key - GLFW_KEY_1);
                if (index < state.catalog.size()) {
                    state.openRequest = state.catalog[index].path;
                }
            }
            break;
        }
    }
}

} // namespace tumble::viewer
