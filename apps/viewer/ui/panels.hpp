// The ImGui panels, one function per panel (each in its own file), and the layout that places
// them: run controls, scenario picker, parameters and view options on the left; inspector,
// impulse tool and plots on the right; the log along the bottom.
#pragma once

#include "viewer/viewer_state.hpp"

namespace tumble::viewer::ui {

/// Play/pause, single step, reset, time scale, the simulated time, errors.
void drawRunControls(ViewerState& state);
/// The scenarios/ files (number keys 1..9 for the first nine) and reload from disk.
void drawScenarioPicker(ViewerState& state);
/// Gravity, dt, integrator and response; the selected body's mass, size and material.
void drawParameters(ViewerState& state);
/// What to draw (axes, vectors, contacts, impulses, shadow), arrow scales, camera follow.
void drawViewOptions(ViewerState& state);
/// The selected body's state, energies, inverse inertia and contact.
void drawInspector(ViewerState& state);
/// An impulse at an offset, a target to solve for, and the handouts' impulse experiments.
void drawImpulseTool(ViewerState& state);
/// Height, speeds and energies over the last seconds, with collisions marked.
void drawPlots(ViewerState& state);
/// The `tumble run` console lines.
void drawLog(ViewerState& state);

/// A combo choosing the selected body (nothing when the scenario has one body).
void drawBodySelector(ViewerState& state);

/// All panels, placed around the 3D view.
void drawPanels(ViewerState& state);

} // namespace tumble::viewer::ui
