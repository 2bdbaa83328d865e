// What every stage of a step reads of the world: its settings, its static geometry and the time.
#pragma once

#include "tumble/material.hpp"
#include "tumble/settings.hpp"
#include "tumble/shape.hpp"

#include <cstdint>
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
    /// How many times the world's bodies or static geometry were edited by hand: what was kept
    /// from a step before an edit is not kept after it (12.5b).
    std::uint64_t edits = 0;
};

} // namespace tumble
