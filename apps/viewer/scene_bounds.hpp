// The part of a scenario the default view frames: where its bodies go during the run, and the
// ground under them.
#pragma once

#include "viewer/camera.hpp"

#include "tumble/scenario/scenario.hpp"

namespace tumble::viewer {

/// The run is looked at for at most this long (s) and this many steps when framing it.
inline constexpr double kFramedSeconds = 20.0;
inline constexpr long long kFramedSteps = 20000;

/// Bounds holding every body's bounding sphere at its starting position and, with a ground,
/// the ground under each body.
ViewBounds sceneBounds(const scenario::Scenario& scenario);

/// Bounds of the run: like sceneBounds, at the positions the bodies take over the scenario's
/// duration (at most kFramedSeconds and kFramedSteps, sampled about 200 times), found by a
/// Runner of its own. The default view frames them, so the bodies stay in sight as they move.
ViewBounds runBounds(const scenario::Scenario& scenario);

/// Where a scene without ground gets its reference grid: 1 m below the lowest point any body's
/// bounding sphere reaches at the start.
float referenceGridHeight(const scenario::Scenario& scenario);

} // namespace tumble::viewer
