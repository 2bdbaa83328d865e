// The step of an island of bodies that may touch each other or static geometry other than the
// ground alone: narrow phase, impacts in time order, resting contact, positions, push-out
// (docs/physics/11-island-solver.md).
#pragma once

#include "body_slot.hpp"
#include "collision/pair_manifold.hpp"
#include "step/step_context.hpp"
#include "step/step_events.hpp"

#include <span>
#include <utility>
#include <vector>

namespace tumble {

/// What the broad phase and the islands hand to the coupled step.
struct CoupledIsland {
    /// Slot indices of the island's dynamic bodies, ascending.
    std::vector<std::uint32_t> bodies;
    /// Pairs of slot indices (lower first) whose boxes swept over the step overlap: both in
    /// `bodies`, or one of them a static body.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    /// Each pair's sides as the island's solver bodies: a body's index in `bodies`, and
    /// bodies.size() for a static side.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairSolvers;
    /// Empty, or each pair's points within the narrow phase's margin over the whole step, found
    /// by the broad phase's test (mayTouch) while the pair's geometry was at hand; valid for
    /// the step (the soft step's narrow phase reads them instead of asking the pair again).
    std::vector<const PairManifold*> pairManifolds;
    /// With pairManifolds, 1 where the pair's manifold has points: the narrow phase places its
    /// contacts from these bytes rather than from the manifolds, a cache line each.
    std::vector<std::uint8_t> pairHasPoints;
    /// (12.5b) Whether the soft step goes on the manifolds the island's lowest body kept (set
    /// by the world before the islands advance).
    bool keepsSoftManifolds = false;
};

/// Advances the island's bodies by dt together. Writes only the slots of `island.bodies`.
void advanceCoupled(const CoupledIsland& island, std::span<BodySlot> slots,
                    const StepContext& context, Real dt, StepEvents& events);

} // namespace tumble
