// Where the panels sit, and the part of the window they leave to the 3D view. Pure: the capture
// tests use it to know where to look.
#pragma once

#include "viewer/camera.hpp"

#include <glm/glm.hpp>

namespace tumble::viewer::ui {

/// Gap between the panels and the window's border, pixels.
inline constexpr float kMargin = 8.0f;
/// Widths of the left column (run, scenario, parameters, view) and of the right column
/// (inspector, plots, impulse tool), and the height of the log along the bottom, pixels, in a
/// window wide enough for them.
inline constexpr float kLeftWidth = 330.0f;
inline constexpr float kRightWidth = 370.0f;
inline constexpr float kLogHeight = 170.0f;
/// In a narrower window the columns shrink to these shares of its width, so the 3D view keeps at
/// least the rest (issue 14, item 18).
inline constexpr float kLeftShare = 0.24f;
inline constexpr float kRightShare = 0.27f;

/// The two columns' widths in a display this wide, pixels.
float leftWidth(float displayWidth);
float rightWidth(float displayWidth);

/// The panels' places in a display of this size: the two columns, and the log between them
/// along the bottom.
ViewRegion leftColumn(const glm::vec2& display);
ViewRegion rightColumn(const glm::vec2& display);
ViewRegion logRegion(const glm::vec2& display);

/// The 3D view's place: between the columns, above the log. A display too small for the panels
/// gives the 3D view the whole of itself.
ViewRegion freeViewRegion(const glm::vec2& display);

} // namespace tumble::viewer::ui
