// World's step stages after the broad phase (world_pairs.cpp): the islands and the coupled
// islands' advance (docs/physics/10-broad-phase.md, 11-island-solver.md).
#include "tumble/world.hpp"

#include "body_slot.hpp"
#include "dynamics/islands.hpp"
#include "dynamics/rest.hpp"
#include "parallel_for.hpp"
#include "step/coupled_step.hpp"
#include "step/island_contacts.hpp"
#include "step/soft_step.hpp"
#include "step/step_scratch.hpp"

#include <algorithm>
#include <cmath>

#ifdef TUMBLE_HAVE_OPENMP
#include <omp.h>
#endif

namespace tumble {

namespace {

/// Whether a box can come within `tolerance` of the half-space: its lowest corner along the
/// normal, n . c - sum |n_i| e_i, against the plane.
bool mayReach(const Aabb& box, const StaticPlane& plane, Real tolerance)
{
    const Vec3 centre = 0.5 * (box.min + box.max);
    const Vec3 half = 0.5 * (box.max - box.min);
    const Real lowest = glm::dot(plane.normal, centre - plane.point) -
                        glm::dot(glm::abs(plane.normal), half);
    return lowest <= tolerance;
}

} // namespace

void World::buildStepIslands(detail::StepScratch& scratch, Real dt)
{
    // no pairs and no half-spaces: every body is alone with the ground (and nothing allocates)
    if (scratch.links.empty() && m_planes.empty()) {
        scratch.islands.clear();
        for (BodySlot& slot : m_slots) {
            slot.coupled = false;
        }
        return;
    }
    // last step's islands are filled again where they lie, so their vectors keep their memory
    std::size_t built = 0;
    scratch.dynamic.assign(m_slots.size(), 0);
    for (std::size_t index = 0; index < m_slots.size(); ++index) {
        const BodySlot& slot = m_slots[index];
        scratch.dynamic[index] = slot.alive && !slot.body.isStatic();
    }
    const Islands islands = buildIslands(m_slots.size(), scratch.dynamic, scratch.links);
    scratch.islandIndex.resize(m_slots.size());
    const IslandLinks links = linksOf(islands, scratch.links);
    for (std::size_t k = 0; k < islands.count(); ++k) {
        const std::span<const std::uint32_t> bodies = islands.island(k);
        const std::span<const std::uint32_t> islandLinks = links.island(k);
        // (7.4): an island sleeps as a whole, and wakes as a whole when one of its bodies wakes
        const bool awake = std::any_of(bodies.begin(), bodies.end(), [&](std::uint32_t body) {
            return !m_slots[body].body.asleep;
        });
        if (!awake) {
            for (const std::uint32_t body : bodies) {
                m_slots[body].coupled = false;
            }
            continue;
        }
        for (const std::uint32_t body : bodies) {
            Body& woken = m_slots[body].body;
            if (woken.asleep) {
                woken.asleep = false;
                woken.slowTime = 0.0;
            }
        }
        // the exact path takes a body alone whose only possible obstacle is the ground
        bool coupled = bodies.size() > 1 || !islandLinks.empty();
        for (const StaticPlane& plane : m_planes) {
            coupled = coupled || mayReach(scratch.sweptBoxes[bodies.front()], plane,
                                          m_settings.contactTolerance);
        }
        for (const std::uint32_t body : bodies) {
            // written only when it changes: a line written here would cross to the core that
            // finishes the body
            if (m_slots[body].coupled != coupled) {
                m_slots[body].coupled = coupled;
            }
        }
        if (!coupled) {
            continue;
        }
        if (built == scratch.islands.size()) {
            scratch.islands.emplace_back();
        }
        CoupledIsland& island = scratch.islands[built++];
        island.bodies.assign(bodies.begin(), bodies.end());
        addIslandPairs(scratch, islandLinks, island, dt);
    }
    scratch.islands.resize(built);
}

void World::addIslandPairs(detail::StepScratch& scratch, std::span<const std::uint32_t> links,
                           CoupledIsland& island, Real dt)
{
    island.pairs.clear();
    island.pairSolvers.clear();
    island.pairManifolds.clear();
    island.pairHasPoints.clear();
    const std::span<const std::uint32_t> bodies = island.bodies;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        scratch.islandIndex[bodies[i]] = static_cast<std::uint32_t>(i);
    }
    const auto solverOf = [&](std::uint32_t slot) {
        return m_slots[slot].body.isStatic() ? static_cast<std::uint32_t>(bodies.size())
                                             : scratch.islandIndex[slot];
    };
    for (const std::uint32_t link : links) {
        const ProxyPair& pair = scratch.links[link];
        const std::uint32_t lower = std::min(pair.a, pair.b);
        const std::uint32_t upper = std::max(pair.a, pair.b);
        island.pairs.emplace_back(lower, upper);
        island.pairSolvers.emplace_back(solverOf(lower), solverOf(upper));
        if (scratch.pairManifolds.empty()) {
            continue;
        }
        const std::uint32_t broadPair = scratch.linkPairs[link];
        if (scratch.pairAtRest[broadPair] != 0) {
            // (10.4b): the island woke in this step; its resting pair's points are those of
            // the test over the same horizon
            findPairPoints(scratch, broadPair, lower, upper, dt);
        }
        island.pairManifolds.push_back(&scratch.pairManifolds[broadPair]);
        island.pairHasPoints.push_back(scratch.pairHasPoints[broadPair]);
    }
    if (!scratch.pairManifolds.empty()) {
        findKeptPairPoints(scratch, links, island, dt);
    }
}

void World::findPairPoints(detail::StepScratch& scratch, std::uint32_t broadPair,
                           std::uint32_t lower, std::uint32_t upper, Real dt)
{
    mayTouch(m_slots, lower, upper, m_settings.contactTolerance,
             reachOver(m_slots[lower].body, m_settings.gravity, dt),
             reachOver(m_slots[upper].body, m_settings.gravity, dt), true,
             &scratch.pairManifolds[broadPair]);
    scratch.pairHasPoints[broadPair] = scratch.pairManifolds[broadPair].pointCount > 0 ? 1 : 0;
}

void World::advanceCoupledIslands(detail::StepScratch& scratch, Real dt)
{
    if (scratch.islandEvents.size() < scratch.islands.size()) {
        scratch.islandEvents.resize(scratch.islands.size());
    }
    const StepContext context = stepContext();
    const auto advance = [&](std::size_t k, const StepContext& used) {
        const CoupledIsland& island = scratch.islands[k];
        StepEvents& events = scratch.islandEvents[k];
        events.clear();
        for (const std::uint32_t body : island.bodies) {
            m_slots[body].body.ledger.impactWorkLastStep = 0.0;
        }
        if (m_settings.solver == ContactSolver::Soft) {
            advanceSoft(island, m_slots, used, dt, events);
        } else {
            advanceCoupled(island, m_slots, used, dt, events);
        }
        updateIslandRest(island.bodies, m_slots, used, dt, events);
    };
    // (11.5c): a large island takes all the threads inside its step, one island after the
    // other; the small ones share the threads between them, each on one. An island is large if
    // it has more than a thread's share of the pairs: islands of a thread's share or less keep
    // the threads as busy side by side, without meeting inside a step. An island writes only
    // its own bodies and its result does not depend on the threads it gets, so neither the
    // split nor the order changes anything.
    std::size_t allPairs = 0;
    for (const CoupledIsland& island : scratch.islands) {
        allPairs += island.pairs.size();
    }
    const auto threadShare = allPairs / static_cast<std::size_t>(std::max(context.threads, 1));
    scratch.smallIslands.clear();
    for (std::uint32_t k = 0; k < scratch.islands.size(); ++k) {
        const std::size_t pairs = scratch.islands[k].pairs.size();
        if (pairs >= detail::kLargeIslandPairs && pairs > threadShare && context.threads > 1) {
            advance(k, context);
        } else {
            scratch.smallIslands.push_back(k);
        }
    }
    StepContext alone = context;
    alone.threads = 1;
    const auto count = static_cast<std::ptrdiff_t>(scratch.smallIslands.size());
    if (count > 1 && context.threads > 1) {
        [[maybe_unused]] const int threads = context.threads;
#ifdef TUMBLE_HAVE_OPENMP
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
#endif
        for (std::ptrdiff_t k = 0; k < count; ++k) {
            advance(scratch.smallIslands[static_cast<std::size_t>(k)], alone);
        }
    } else {
        for (std::ptrdiff_t k = 0; k < count; ++k) {
            advance(scratch.smallIslands[static_cast<std::size_t>(k)], alone);
        }
    }
}

} // namespace tumble
