// The handouts' impulse experiments (part 2 task 2, part 3 task 1) as the impulse tools of the
// viewer and of the web page offer them: one per [[impulse]] entry of a loaded scenario.
#pragma once

#include "tumble/math.hpp"
#include "tumble/scenario/scenario.hpp"

#include <optional>
#include <string>
#include <vector>

namespace tumble::scenario {

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

/// The impulse experiments of a loaded scenario, labelled `labelPrefix` when it holds one and
/// "<labelPrefix>: <body>" when it holds several; an entry naming no body of the file is left out.
std::vector<ImpulseExperiment> impulseExperiments(const Scenario& loaded,
                                                  const std::string& labelPrefix);

} // namespace tumble::scenario
