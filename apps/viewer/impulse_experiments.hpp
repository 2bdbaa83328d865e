// The handouts' impulse experiments (part 2 task 2, part 3 task 1), read from their scenario
// files, for the impulse tool's buttons.
#pragma once

#include "tumble/math.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace tumble::viewer {

/// One [[impulse]] entry of a handout file, with the velocities its body starts with.
struct ImpulseExperiment {
    /// "part 2 task 2: left_spin", "part 3 task 1".
    std::string label;
    Vec3 startVelocity{0.0};
    Vec3 startAngularVelocity{0.0};
    /// A target to solve for (when targetVelocity is set) or an impulse at an offset.
    std::optional<Vec3> targetVelocity;
    std::optional<Vec3> targetAngularVelocity;
    Vec3 impulse{0.0};
    Vec3 offset{0.0};
};

/// Handout files holding impulse experiments, and the label prefix of each.
struct ExperimentFile {
    const char* fileName;
    const char* label;
};
inline constexpr ExperimentFile kExperimentFiles[] = {
    {"part2_task2_impulses.toml", "part 2 task 2"},
    {"part3_task1_impulse.toml", "part 3 task 1"},
};

/// Every impulse experiment of the files above found in `directory`; a file that is missing or
/// does not load contributes none.
std::vector<ImpulseExperiment> loadImpulseExperiments(const std::filesystem::path& directory);

} // namespace tumble::viewer
