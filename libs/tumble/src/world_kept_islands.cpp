// Soft islands kept from the last step (docs/physics/12-soft-step.md, (12.5b)): the broad
// phase's answers for their pairs (a pair within an island whose bodies all stayed put touches
// as it did when its manifolds were built), and which islands keep their manifolds.
#include "tumble/world.hpp"

#include "body_slot.hpp"
#include "parallel_for.hpp"
#include "step/coupled_step.hpp"
#include "step/island_contacts.hpp"
#include "step/soft_kept_island.hpp"
#include "step/step_scratch.hpp"

#include <algorithm>

namespace tumble {

void World::markKeptSoftIslands(detail::StepScratch& scratch) const
{
    scratch.keptLeader.assign(m_slots.size(), detail::kNotKept);
    scratch.keptBodies = 0;
    if (m_settings.solver != ContactSolver::Soft) {
        return;
    }
    scratch.keptPairsFirst.resize(m_slots.size());
    scratch.keptPairsEnd.resize(m_slots.size());
    for (std::uint32_t index = 0; index < m_slots.size(); ++index) {
        const BodySlot& slot = m_slots[index];
        const SoftKeptIsland& kept = slot.softKept;
        // the kept island first: only its leader's slot is read further
        if (!kept.valid || !slot.alive || slot.body.asleep || kept.edits != m_edits ||
            !softBodiesStill(*kept.buffers, kept.bodies, m_slots, threadCount())) {
            continue;
        }
        scratch.keptBodies += kept.bodies.size();
        for (const std::uint32_t body : kept.bodies) {
            scratch.keptLeader[body] = index;
            scratch.keptPairsFirst[body] = 0;
            scratch.keptPairsEnd[body] = 0;
        }
        // the pairs are sorted by their lower side: each body's run of them, so that a pair is
        // found among a handful (a static lower side is any island's, and is searched for)
        const auto& pairs = kept.pairs;
        std::size_t first = 0;
        while (first < pairs.size()) {
            const std::uint32_t lower = pairs[first].first;
            std::size_t end = first + 1;
            while (end < pairs.size() && pairs[end].first == lower) {
                ++end;
            }
            if (scratch.keptLeader[lower] == index) {
                scratch.keptPairsFirst[lower] = static_cast<std::uint32_t>(first);
                scratch.keptPairsEnd[lower] = static_cast<std::uint32_t>(end);
            }
            first = end;
        }
    }
}

std::optional<bool> World::keptSoftTouch(const detail::StepScratch& scratch,
                                         std::uint32_t lower, std::uint32_t upper) const
{
    if (scratch.keptLeader.empty()) {
        return std::nullopt;
    }
    const std::uint32_t leaderLower = scratch.keptLeader[lower];
    const std::uint32_t leaderUpper = scratch.keptLeader[upper];
    // static geometry does not move unless edited, and an edit ends every kept island
    const bool withinOne = leaderLower != detail::kNotKept &&
                           (leaderLower == leaderUpper || m_slots[upper].body.isStatic());
    const bool withStatic =
        leaderUpper != detail::kNotKept && m_slots[lower].body.isStatic();
    if (!withinOne && !withStatic) {
        return std::nullopt;
    }
    const std::uint32_t leader = withinOne ? leaderLower : leaderUpper;
    const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs =
        m_slots[leader].softKept.pairs;
    if (!withinOne) {
        return std::binary_search(pairs.begin(), pairs.end(), std::pair{lower, upper});
    }
    const auto first = pairs.begin() + scratch.keptPairsFirst[lower];
    const auto end = pairs.begin() + scratch.keptPairsEnd[lower];
    return std::any_of(first, end, [&](const auto& pair) { return pair.second == upper; });
}

void World::decideKeptSoftIslands(detail::StepScratch& scratch)
{
    if (m_settings.solver != ContactSolver::Soft) {
        return;
    }
    const int threads = threadCount();
    scratch.leadsKeptIsland.assign(m_slots.size(), 0);
    for (CoupledIsland& island : scratch.islands) {
        // its bodies stayed put if the broad phase found them so (markKeptSoftIslands)
        const std::uint32_t leader = island.bodies.front();
        island.keepsSoftManifolds = scratch.keptLeader[leader] == leader &&
                                    softKeptFor(m_slots[leader].softKept, island, m_edits);
        scratch.leadsKeptIsland[leader] = island.keepsSoftManifolds ? 1 : 0;
    }
    // before any island reads its bodies' caches, or a body alone clears its own
    for (std::uint32_t index = 0; index < m_slots.size(); ++index) {
        if (m_slots[index].softKept.unstored && scratch.leadsKeptIsland[index] == 0) {
            storeKeptSoftIsland(m_slots[index].softKept, m_slots, threads);
        }
    }
}

void World::findKeptPairPoints(detail::StepScratch& scratch,
                               std::span<const std::uint32_t> links, CoupledIsland& island,
                               Real dt)
{
    if (softKeptFor(m_slots[island.bodies.front()].softKept, island, m_edits)) {
        return;
    }
    // the island is not the one kept: its step builds its manifolds, from every pair's points
    for (std::size_t i = 0; i < links.size(); ++i) {
        const std::uint32_t broadPair = scratch.linkPairs[links[i]];
        if (scratch.pairFromKept[broadPair] == 0) {
            continue;
        }
        const auto [lower, upper] = island.pairs[i];
        findPairPoints(scratch, broadPair, lower, upper, dt);
        island.pairHasPoints[i] = scratch.pairHasPoints[broadPair];
    }
}

} // namespace tumble
