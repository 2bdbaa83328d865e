// The keys a scenario file may use, table by table (docs/scenario-format.md lists them all).
#pragma once

#include <array>
#include <string_view>

namespace tumble::scenario::detail {

inline constexpr std::array<std::string_view, 7> kTopLevelKeys{
    "world", "ground", "plane", "body", "impulse", "spawn", "throw"};

inline constexpr std::array<std::string_view, 17> kWorldKeys{
    "gravity", "dt", "duration", "integrator", "response", "contact_tolerance",
    "restitution_threshold", "solver_iterations", "solver", "soft_substeps", "soft_contact_hertz",
    "soft_damping_ratio", "soft_push_speed", "sleep", "sleep_linear_speed", "sleep_angular_speed",
    "sleep_time"};

inline constexpr std::array<std::string_view, 4> kGroundKeys{"height", "elasticity", "friction",
                                                            "static_friction"};

inline constexpr std::array<std::string_view, 5> kPlaneKeys{"point", "normal", "elasticity",
                                                           "friction", "static_friction"};

/// The keys of a material; a static body or a plane that gives none takes the dynamic body's.
inline constexpr std::array<std::string_view, 3> kMaterialKeys{"elasticity", "friction",
                                                              "static_friction"};

inline constexpr std::array<std::string_view, 12> kBodyKeys{
    "name", "motion", "size", "scale", "mass", "position", "orientation", "velocity",
    "angular_velocity", "elasticity", "friction", "static_friction"};

/// What a static body may not have: it does not move, and no contact moves it.
inline constexpr std::array<std::string_view, 3> kDynamicOnlyBodyKeys{"mass", "velocity",
                                                                      "angular_velocity"};

/// Values of body.motion, in the order of BodyMotion's enumerators.
inline constexpr std::array<std::string_view, 2> kMotionNames{"dynamic", "static"};

inline constexpr std::array<std::string_view, 6> kImpulseKeys{
    "at", "body", "impulse", "offset", "velocity", "angular_velocity"};

inline constexpr std::array<std::string_view, 12> kSpawnKeys{
    "count", "seed", "spacing", "size", "mass", "height", "orientation", "angular_speed",
    "velocity", "elasticity", "friction", "static_friction"};
inline constexpr std::array<std::string_view, 10> kThrowKeys{
    "height",   "speed",   "heading",        "vertical_speed", "angular_speed",
    "orientation", "max_time", "release", "cluster_radius", "region"};

inline constexpr std::array<std::string_view, 2> kThrowRegionKeys{"min", "max"};

inline constexpr std::array<std::string_view, 2> kAxisAngleKeys{"axis", "degrees"};

/// Values of world.integrator and world.response, in the order of the library's enumerators.
inline constexpr std::array<std::string_view, 2> kIntegratorNames{"exact", "handout"};
inline constexpr std::array<std::string_view, 2> kResponseNames{"sequential", "average"};
/// Values of world.solver, in the order of ContactSolver's enumerators.
inline constexpr std::array<std::string_view, 2> kSolverNames{"exact", "soft"};
/// Values of throw.orientation, in the order of ThrowOrientation's enumerators.
inline constexpr std::array<std::string_view, 2> kThrowOrientationNames{"random", "body"};

inline constexpr std::array<std::string_view, 2> kThrowReleaseNames{"each", "cluster"};

} // namespace tumble::scenario::detail
