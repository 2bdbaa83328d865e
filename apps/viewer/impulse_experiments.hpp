// The handouts' impulse experiments (part 2 task 2, part 3 task 1), read from their scenario
// files, for the impulse tool's buttons.
#pragma once

#include "tumble/scenario/impulse_experiments.hpp"

#include <filesystem>
#include <vector>

namespace tumble::viewer {

using scenario::ImpulseExperiment;

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
