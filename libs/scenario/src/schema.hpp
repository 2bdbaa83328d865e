// The keys a scenario file may use, table by table (docs/scenario-format.md lists them all).
#pragma once

#include <array>
#include <string_view>

namespace tumble::scenario::detail {

inline constexpr std::array<std::string_view, 6> kTopLevelKeys{
    "world", "ground", "body", "impulse", "spawn", "throw"};

inline constexpr std::array<std::string_view, 12> kWorldKeys{
    "gravity", "dt", "duration", "integrator", "response", "contact_tolerance",
    "restitution_threshold", "solver_iterations", "sleep", "sleep_linear_speed",
    "sleep_angular_speed", "sleep_time"};

inline constexpr std::array<std::string_view, 1> kGroundKeys{"height"};

inline constexpr std::array<std::string_view, 11> kBodyKeys{
    "name", "size", "scale", "mass", "position", "orientation", "velocity", "angular_velocity",
    "elasticity", "friction", "static_friction"};

inline constexpr std::array<std::string_view, 6> kImpulseKeys{
    "at", "body", "impulse", "offset", "velocity", "angular_velocity"};

inline constexpr std::array<std::string_view, 12> kSpawnKeys{
    "count", "seed", "spacing", "size", "mass", "height", "orientation", "angular_speed",
    "velocity", "elasticity", "friction", "static_friction"};
inline constexpr std::array<std::string_view, 6> kThrowKeys{
    "height", "speed", "vertical_speed", "angular_speed", "orientation", "max_time"};

inline constexpr std::array<std::string_view, 2> kAxisAngleKeys{"axis", "degrees"};

/// Values of world.integrator and world.response, in the order of the library's enumerators.
inline constexpr std::array<std::string_view, 2> kIntegratorNames{"exact", "handout"};
inline constexpr std::array<std::string_view, 2> kResponseNames{"sequential", "average"};
/// Values of throw.orientation, in the order of ThrowOrientation's enumerators.
inline constexpr std::array<std::string_view, 2> kThrowOrientationNames{"random", "body"};

} // namespace tumble::scenario::detail
