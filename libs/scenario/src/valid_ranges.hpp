// The valid ranges of scenario values beyond "finite" and "positive": what the robustness tests
// (tests/robustness) show tumble handles, so larger or smaller values are rejected at load time
// instead of producing a run that cannot be trusted. docs/scenario-format.md lists them and
// docs/robustness.md is generated from this table.
#pragma once

#include "tumble/math.hpp"

#include <array>
#include <string_view>

namespace tumble::scenario::detail {

/// One checked quantity: [low, high] in `unit`. For a vector the bound is on its length.
struct ValidRange {
    std::string_view key;
    Real low;
    Real high;
    std::string_view unit;
};

inline constexpr ValidRange kDtRange{"world.dt", 1e-6, 0.1, "s"};
/// Steps in one run (duration / dt): beyond this a run would take days and the step counter
/// loses its meaning.
inline constexpr ValidRange kStepCountRange{"world.duration / world.dt", 0.0, 1e9, "steps"};
inline constexpr ValidRange kGravityRange{"world.gravity", 0.0, 1e3, "m/s^2"};
inline constexpr ValidRange kContactToleranceRange{"world.contact_tolerance", 1e-9, 1e-2, "m"};
inline constexpr ValidRange kGroundHeightRange{"ground.height", -1e6, 1e6, "m"};
inline constexpr ValidRange kMassRange{"mass", 1e-6, 1e6, "kg"};
inline constexpr ValidRange kSizeRange{"size", 1e-3, 1e3, "m"};
/// Longest over shortest edge.
inline constexpr ValidRange kAspectRange{"size (longest / shortest)", 1.0, 1e3, ""};
inline constexpr ValidRange kPositionRange{"position", 0.0, 1e6, "m"};
inline constexpr ValidRange kSpeedRange{"velocity", 0.0, 1e3, "m/s"};
inline constexpr ValidRange kAngularSpeedRange{"angular_velocity", 0.0, 1e3, "rad/s"};
/// |angular_velocity| dt: the exact rotation's energy error grows as (|w| dt)^2
/// (docs/robustness.md); half a radian per step keeps it below about 0.3 %.
inline constexpr ValidRange kTurnPerStepRange{"angular_velocity * world.dt", 0.0, 0.5, "rad"};
inline constexpr ValidRange kFrictionRange{"friction", 0.0, 10.0, ""};
inline constexpr ValidRange kImpulseRange{"impulse", 0.0, 1e9, "N s"};
inline constexpr ValidRange kOffsetRange{"offset", 0.0, 1e3, "m"};

inline constexpr std::array<ValidRange, 15> kValidRanges{
    kDtRange,           kStepCountRange,   kGravityRange,      kContactToleranceRange,
    kGroundHeightRange, kMassRange,        kSizeRange,         kAspectRange,
    kPositionRange,     kSpeedRange,       kAngularSpeedRange, kTurnPerStepRange,
    kFrictionRange,     kImpulseRange,     kOffsetRange};

} // namespace tumble::scenario::detail
