// World's step stages around the solvers: the broad phase, the islands and the coupled islands'
// advance (docs/physics/10-broad-phase.md, 11-island-solver.md).
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

/// (11.5c): an island of at least this many linked pairs (some kColouredSweepPoints points, at
/// four a face contact) is large: it takes all the threads inside its step. The broad phase's
/// touch test takes the threads from as many pairs.
constexpr std::size_t kLargeIslandPairs = 256;
/// A world of at least this many slots finds its bodies' boxes and forgets its pairs gone over
/// the threads.
constexpr std::size_t kLargeWorldSlots = 1024;
/// Bodies whose pairs a thread takes at a time in the touch test: a pair whose geometry is
/// carried or searched costs many times one whose geometry is kept, and the bodies that moved
/// lie together (the lower layers of a pile, what just landed).
constexpr std::size_t kPairOwnersPerChunk = 16;
/// How many pairs ahead a body's kept geometry is asked for (prefetch.hpp).
constexpr std::size_t kPairsPrefetchedAhead = 4;

/// A bound on the angular speed over a torque-free step: |w| <= |L| / I_min <= |w0| I_max / I_min
/// (the swept box of (10.3) needs one for the whole step).
Vec3 angularSpeedBound(const Body& body)
{
    const Vec3 inertia = body.inertiaBody();
    const Real ratio = std::max({inertia.x, inertia.y, inertia.z}) /
                       std::min({inertia.x, inertia.y, inertia.z});
    return body.angularVelocity * ratio;
}

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

/// Whether the body keeps its pose over the step unless an island wakes it: static or asleep.
bool restsThisStep(const Body& body)
{
    return body.isStatic() || body.asleep;
}

} // namespace

void World::findPairs(detail::StepScratch& scratch, Real dt)
{
    scratch.proxies.clear();
    scratch.sweptBoxes.assign(m_slots.size(), Aabb{});
    const Real margin = m_settings.contactTolerance;
    const int slotThreads = m_slots.size() >= kLargeWorldSlots ? threadCount() : 1;
    // each slot writes only its own box
    parallelFor(m_slots.size(), slotThreads, [&](std::size_t index) {
        const BodySlot& slot = m_slots[index];
        if (!slot.alive) {
            return;
        }
        const Body& body = slot.body;
        const Transform pose{body.position, body.orientation};
        // a sleeping body does not move, but pairs like any dynamic body: its island wakes
        // with it (7.4)
        const bool moving = !restsThisStep(body);
        scratch.sweptBoxes[index] =
            moving ? sweptCuboidAabb(pose, body.shape.halfExtents(), body.linearVelocity,
                                     m_settings.gravity, angularSpeedBound(body), dt, margin)
                   : expanded(cuboidAabb(pose, body.shape.halfExtents()), margin);
    });
    for (std::uint32_t index = 0; index < m_slots.size(); ++index) {
        if (m_slots[index].alive) {
            scratch.proxies.push_back(BroadPhaseProxy{scratch.sweptBoxes[index], index,
                                                      !m_slots[index].body.isStatic()});
        }
    }
    scratch.broadPhase.update(scratch.proxies, threadCount());
    // narrow phase's first test: boxes that cannot touch within the step link nothing, and a
    // body near another but apart keeps the exact path (10.4)
    const std::span<const ProxyPair> pairs = scratch.broadPhase.pairs();
    scratch.pairTouches.assign(pairs.size(), 0);
    const bool carry = m_settings.solver == ContactSolver::Soft;
    scratch.pairManifolds.resize(carry ? pairs.size() : 0);
    scratch.pairHasPoints.assign(carry ? pairs.size() : 0, 0);
    scratch.pairAtRest.assign(pairs.size(), 0);
    // each body's reach once when the pairs outnumber the bodies (3.4 a body on the pyramid),
    // else each pair's two (most bodies of a scene of bodies alone pair with none)
    scratch.reach.clear();
    if (pairs.size() > m_slots.size()) {
        scratch.reach.resize(m_slots.size());
        parallelFor(m_slots.size(), slotThreads, [&](std::size_t index) {
            scratch.reach[index] = m_slots[index].alive
                                       ? reachOver(m_slots[index].body, m_settings.gravity, dt)
                                       : 0.0;
        });
    }
    const auto testPair = [&](std::size_t k) { testBroadPair(scratch, k, dt); };
    const int threads = pairs.size() >= kLargeIslandPairs ? threadCount() : 1;
    if (threads > 1) {
        // a pair writes the geometry its dynamic body keeps (9.11): each body's pairs go to
        // one thread, in their order (11.5c)
        scratch.pairOwners.resize(pairs.size());
        for (std::size_t k = 0; k < pairs.size(); ++k) {
            const std::uint32_t a = scratch.proxies[pairs[k].a].body;
            const std::uint32_t b = scratch.proxies[pairs[k].b].body;
            scratch.pairOwners[k] = pairGeometryOwner(m_slots, std::min(a, b), std::max(a, b));
        }
        scratch.pairGroups.build(scratch.pairOwners, m_slots.size());
        const OwnerGroups& groups = scratch.pairGroups;
        parallelForBalanced(groups.count(), threads, kPairOwnersPerChunk, [&](std::size_t g) {
            if (g + 1 < groups.count() && !groups.group(g + 1).empty()) {
                m_slots[scratch.pairOwners[groups.group(g + 1).front()]].pairGeometry.prefetch();
            }
            for (const std::uint32_t k : groups.group(g)) {
                testPair(k);
            }
        });
    } else {
        // the pairs come sorted by their lower slot: a body's kept geometry is asked for ahead
        // of its first pair
        const auto lowerOf = [&](std::size_t k) {
            return std::min(scratch.proxies[pairs[k].a].body, scratch.proxies[pairs[k].b].body);
        };
        for (std::size_t k = 0; k < pairs.size(); ++k) {
            const std::size_t ahead = k + kPairsPrefetchedAhead;
            if (ahead < pairs.size() && lowerOf(ahead) != lowerOf(ahead - 1)) {
                m_slots[lowerOf(ahead)].pairGeometry.prefetch();
            }
            testPair(k);
        }
    }
    scratch.links.clear();
    scratch.linkPairs.clear();
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        if (scratch.pairTouches[k] != 0) {
            scratch.links.push_back(
                {scratch.proxies[pairs[k].a].body, scratch.proxies[pairs[k].b].body});
            scratch.linkPairs.push_back(static_cast<std::uint32_t>(k));
        }
    }
    // (9.11): kept geometry nobody asked for since the last broad phase is of a pair gone
    parallelFor(m_slots.size(), slotThreads,
                [&](std::size_t index) { m_slots[index].pairGeometry.forgetUnasked(); });
}

void World::testBroadPair(detail::StepScratch& scratch, std::size_t k, Real dt)
{
    const ProxyPair& pair = scratch.broadPhase.pairs()[k];
    const std::uint32_t a = scratch.proxies[pair.a].body;
    const std::uint32_t b = scratch.proxies[pair.b].body;
    const std::uint32_t lower = std::min(a, b);
    const std::uint32_t upper = std::max(a, b);
    // each side's reach found here, not for every body: most bodies of a scene of bodies alone
    // pair with none
    const auto reachOf = [&](std::uint32_t slot) {
        return scratch.reach.empty() ? reachOver(m_slots[slot].body, m_settings.gravity, dt)
                                     : scratch.reach[slot];
    };
    const Real reachLower = reachOf(lower);
    const Real reachUpper = reachOf(upper);
    const Real tolerance = m_settings.contactTolerance;
    // the soft step carries a pair's geometry with its bodies (9.12), and its narrow phase over
    // the same step reads the points found here
    const bool carry = m_settings.solver == ContactSolver::Soft;
    PairManifold* manifold = carry ? &scratch.pairManifolds[k] : nullptr;
    // (10.4b): a pair neither of whose bodies moves keeps its answer while it rests, and finds
    // its points only if its island wakes (addIslandPairs)
    const bool atRest =
        restsThisStep(m_slots[lower].body) && restsThisStep(m_slots[upper].body);
    scratch.pairAtRest[k] = atRest ? 1 : 0;
    if (atRest && manifold != nullptr) {
        manifold->pointCount = 0;
    }
    const bool touches =
        atRest ? restingMayTouch(m_slots, lower, upper, tolerance, reachLower, reachUpper, carry)
               : mayTouch(m_slots, lower, upper, tolerance, reachLower, reachUpper, carry,
                          manifold);
    scratch.pairTouches[k] = touches ? 1 : 0;
    if (manifold != nullptr) {
        scratch.pairHasPoints[k] = manifold->pointCount > 0 ? 1 : 0;
    }
}

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
            m_slots[body].coupled = coupled;
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
            mayTouch(m_slots, lower, upper, m_settings.contactTolerance,
                     reachOver(m_slots[lower].body, m_settings.gravity, dt),
                     reachOver(m_slots[upper].body, m_settings.gravity, dt), true,
                     &scratch.pairManifolds[broadPair]);
            scratch.pairHasPoints[broadPair] =
                scratch.pairManifolds[broadPair].pointCount > 0 ? 1 : 0;
        }
        island.pairManifolds.push_back(&scratch.pairManifolds[broadPair]);
        island.pairHasPoints.push_back(scratch.pairHasPoints[broadPair]);
    }
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
    // other; the small ones share the threads between them, each on one. An island writes only
    // its own bodies and its result does not depend on the threads it gets, so neither the
    // split nor the order changes anything.
    scratch.smallIslands.clear();
    for (std::uint32_t k = 0; k < scratch.islands.size(); ++k) {
        if (scratch.islands[k].pairs.size() >= kLargeIslandPairs && context.threads > 1) {
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
