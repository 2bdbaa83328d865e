// What every stage of a step reads of the world: its settings, its static geometry and the time.
#pragma once

#include "tumble/material.hpp"
#include "tumble/settings.hpp"
#include "tumble/shape.hpp"

#include <optional>
#include <span>

namespace tumble {

struct StepContext {
    const WorldSettings& settings;
    const std::optional<Plane>& ground;
    /// Simulated time at the start of the step, s.
    Real time = 0.0;
    /// The half-spaces besides the ground.
    std::span<const StaticPlane> planes{};
    /// The ground's own material, or none (its contacts take the dynamic body's).
    std::optional<Material> groundMaterial{};
    /// Threads one island's sweeps may spread over (settings.threads resolved, at least 1).
    int threads = 1;
};

} // namespace tumble
