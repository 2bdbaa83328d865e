// The working buffers of a step, kept from step to step so a steady scene allocates little:
// the broad phase's boxes and pairs, the islands, and the events of each island.
#pragma once

#include "collision/aabb.hpp"
#include "collision/broad_phase.hpp"
#include "collision/pair_manifold.hpp"
#include "step/coupled_step.hpp"
#include "step/owner_groups.hpp"
#include "step/step_events.hpp"
#include "tumble/world.hpp"

#include <vector>

namespace tumble::detail {

/// (11.5c): an island of at least this many linked pairs (some kColouredSweepPoints points, at
/// four a face contact) is large: it takes all the threads inside its step. The broad phase's
/// touch test takes the threads from as many pairs.
inline constexpr std::size_t kLargeIslandPairs = 256;
/// StepScratch::keptLeader of a body in no kept soft island.
inline constexpr std::uint32_t kNotKept = 0xffffffffu;

struct StepScratch {
    std::vector<BroadPhaseProxy> proxies;
    /// The box of each slot over the step (empty for a dead slot).
    std::vector<Aabb> sweptBoxes;
    /// Each slot's reachOver over the step, when found once a body (World::findPairs), else
    /// empty.
    std::vector<Real> reach;
    BroadPhase broadPhase;
    /// Whether each of the broad phase's pairs may touch within the step (10.4).
    std::vector<std::uint8_t> pairTouches;
    /// The pairs not answered by a kept island (12.5b), which the touch test tests; and for
    /// each of them the body whose kept geometry it writes, grouped for the threads (11.5c).
    std::vector<std::uint32_t> pairsTested;
    std::vector<std::uint32_t> pairOwners;
    OwnerGroups pairGroups;
    /// With the soft step, each pair's points within the narrow phase's margin (mayTouch), at
    /// the pair's index; entries past this step's pairs are left from steps with more.
    std::vector<PairManifold> pairManifolds;
    /// With them, 1 where the manifold has points (CoupledIsland::pairHasPoints).
    std::vector<std::uint8_t> pairHasPoints;
    /// 1 for a pair whose bodies both rest (static or asleep) at the test: its answer is the
    /// one kept while it rests, and its points are found only if its island wakes (10.4b).
    std::vector<std::uint8_t> pairAtRest;
    /// Each slot's kept soft island whose bodies all stayed put (its lowest body's slot), or
    /// kNotKept; and 1 for a pair answered from that island's pairs rather than tested (12.5b).
    std::vector<std::uint32_t> keptLeader;
    /// How many slots have a kept leader.
    std::size_t keptBodies = 0;
    /// For a body of such an island, its pairs as the lower side: [first, end) in the
    /// island's sorted pair list.
    std::vector<std::uint32_t> keptPairsFirst;
    std::vector<std::uint32_t> keptPairsEnd;
    std::vector<std::uint8_t> pairFromKept;
    /// 1 for the lowest body of an island that keeps its soft manifolds this step.
    std::vector<std::uint8_t> leadsKeptIsland;
    /// The broad phase's pairs that may touch, as slot indices, and each one's pair index.
    std::vector<ProxyPair> links;
    std::vector<std::uint32_t> linkPairs;
    /// 1 for a live dynamic body, awake or asleep: islands are built over all of them.
    std::vector<std::uint8_t> dynamic;
    std::vector<CoupledIsland> islands;
    /// Each body's index in the island being built.
    std::vector<std::uint32_t> islandIndex;
    std::vector<StepEvents> islandEvents;
    /// Indices of the islands small enough to share the threads between them (11.5c).
    std::vector<std::uint32_t> smallIslands;
};

} // namespace tumble::detail
