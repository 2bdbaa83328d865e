// World's broad phase: each body's box over the step, the sort and sweep, and the touch test
// of each pair of overlapping boxes (docs/physics/10-broad-phase.md, (10.3)-(10.4b)).
#include "tumble/world.hpp"

#include "body_slot.hpp"
#include "parallel_for.hpp"
#include "step/island_contacts.hpp"
#include "step/step_scratch.hpp"

#include <algorithm>

namespace tumble {

namespace {

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
    // (12.5b): a kept soft island that stayed put keeps its pairs' answers
    markKeptSoftIslands(scratch);
    scratch.pairFromKept.assign(pairs.size(), 0);
    scratch.pairTouches.assign(pairs.size(), 0);
    const bool carry = m_settings.solver == ContactSolver::Soft;
    // never shrunk while carried: each entry is written before it is read, and one grown back
    // after a step of fewer pairs would construct (clear) what it grows by on this thread
    if (!carry) {
        scratch.pairManifolds.clear();
    } else if (scratch.pairManifolds.size() < pairs.size()) {
        scratch.pairManifolds.resize(pairs.size());
    }
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
    testBroadPairs(scratch, dt);
    scratch.links.clear();
    scratch.linkPairs.clear();
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        if (scratch.pairTouches[k] != 0) {
            scratch.links.push_back(
                {scratch.proxies[pairs[k].a].body, scratch.proxies[pairs[k].b].body});
            scratch.linkPairs.push_back(static_cast<std::uint32_t>(k));
        }
    }
    // (9.11): kept geometry nobody asked for since the last broad phase is of a pair gone,
    // unless its owner's pairs were answered by its kept island (12.5b); the slots left are
    // shared over the threads only when a large world's are
    const std::size_t forgetting = m_slots.size() - scratch.keptBodies;
    const int forgetThreads = forgetting >= kLargeWorldSlots ? slotThreads : 1;
    parallelFor(forgetting > 0 ? m_slots.size() : 0, forgetThreads, [&](std::size_t index) {
        if (scratch.keptLeader[index] == detail::kNotKept) {
            m_slots[index].pairGeometry.forgetUnasked();
        }
    });
}

void World::testBroadPairs(detail::StepScratch& scratch, Real dt)
{
    const std::span<const ProxyPair> pairs = scratch.broadPhase.pairs();
    // (12.5b): a pair of a kept island is answered by a look-up, cheaper here than the start
    // of a parallel loop and the lines it would send to another core; the pairs left carry or
    // search geometry
    scratch.pairsTested.clear();
    for (std::uint32_t k = 0; k < pairs.size(); ++k) {
        if (!answerFromKeptIsland(scratch, k)) {
            scratch.pairsTested.push_back(k);
        }
    }
    const std::span<const std::uint32_t> tested = scratch.pairsTested;
    const auto lowerOf = [&](std::size_t k) {
        return std::min(scratch.proxies[pairs[k].a].body, scratch.proxies[pairs[k].b].body);
    };
    if (tested.size() < detail::kLargeIslandPairs || threadCount() == 1) {
        // the pairs come sorted by their lower slot: a body's kept geometry is asked for ahead
        // of its first pair
        for (std::size_t i = 0; i < tested.size(); ++i) {
            const std::size_t ahead = i + kPairsPrefetchedAhead;
            if (ahead < tested.size() && lowerOf(tested[ahead]) != lowerOf(tested[ahead - 1])) {
                m_slots[lowerOf(tested[ahead])].pairGeometry.prefetch();
            }
            testBroadPair(scratch, tested[i], dt);
        }
        return;
    }
    // a pair writes the geometry its dynamic body keeps (9.11): each body's pairs go to one
    // thread, in their order (11.5c)
    scratch.pairOwners.resize(tested.size());
    for (std::size_t i = 0; i < tested.size(); ++i) {
        const std::uint32_t a = scratch.proxies[pairs[tested[i]].a].body;
        const std::uint32_t b = scratch.proxies[pairs[tested[i]].b].body;
        scratch.pairOwners[i] = pairGeometryOwner(m_slots, std::min(a, b), std::max(a, b));
    }
    scratch.pairGroups.build(scratch.pairOwners, m_slots.size());
    const OwnerGroups& groups = scratch.pairGroups;
    parallelForBalanced(groups.count(), threadCount(), kPairOwnersPerChunk, [&](std::size_t g) {
        if (g + 1 < groups.count() && !groups.group(g + 1).empty()) {
            m_slots[scratch.pairOwners[groups.group(g + 1).front()]].pairGeometry.prefetch();
        }
        for (const std::uint32_t i : groups.group(g)) {
            testBroadPair(scratch, tested[i], dt);
        }
    });
}

bool World::answerFromKeptIsland(detail::StepScratch& scratch, std::size_t k) const
{
    const ProxyPair& pair = scratch.broadPhase.pairs()[k];
    const std::uint32_t a = scratch.proxies[pair.a].body;
    const std::uint32_t b = scratch.proxies[pair.b].body;
    const std::optional<bool> kept = keptSoftTouch(scratch, std::min(a, b), std::max(a, b));
    if (!kept) {
        return false;
    }
    // its island's step reads no points of it, unless a body joins the island
    // (findKeptPairPoints)
    scratch.pairFromKept[k] = 1;
    scratch.pairTouches[k] = *kept ? 1 : 0;
    if (!scratch.pairManifolds.empty()) {
        scratch.pairManifolds[k].pointCount = 0;
        scratch.pairHasPoints[k] = 0;
    }
    return true;
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

} // namespace tumble
