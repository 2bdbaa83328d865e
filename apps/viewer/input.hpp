// Mouse and keyboard: camera drags and the viewer's keys, read through ImGui so that input a
// panel is using never reaches the scene.
#pragma once

#include "viewer/camera.hpp"
#include "viewer/viewer_state.hpp"
#include "viewer/window.hpp"

#include <span>

namespace tumble::viewer {

/// Left drag orbits, right or middle drag pans, the wheel zooms (unless a panel has the mouse).
void handleMouse(OrbitCamera& camera, float viewportHeight);

/// Space play/pause, N single step, R reset, L reload, F follow, V reset view, X body axes,
/// H hide or show the panels, Esc quit, 1..9 the scenarios in the picker's order (unless a text
/// field has the keyboard).
void handleKeys(ViewerState& state, std::span<const KeyPress> presses);

} // namespace tumble::viewer
