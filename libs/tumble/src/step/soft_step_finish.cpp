// The end of an island's soft step (docs/physics/12-soft-step.md, (12.5), (12.8)): the
// warm-start store, the step's work shared over the bodies, and the bodies written back.
#include "step/soft_island_step.hpp"

#include "body_state.hpp"
#include "dynamics/soft_lanes.hpp"
#include "step/soft_island_manifolds.hpp"
#include "step/soft_warm_start.hpp"

namespace tumble {

IslandWork SoftStep::gatherWork()
{
    const std::size_t count = m_island.bodies.size();
    m_buffers.pushed.assign(m_buffers.contacts.size(), 0);
    IslandWork total;
    if (m_buffers.inLanes) {
        m_buffers.lanes.work(m_buffers.blockWork, m_buffers.pushed, m_context.threads);
        for (const SoftBlockWork& block : m_buffers.blockWork) {
            total.normal += block.normal;
            total.friction += block.friction;
        }
    }
    const std::size_t first = firstUnpackedManifold(m_buffers);
    for (std::size_t i = 0; i < m_buffers.manifolds.size(); ++i) {
        const SoftManifold& manifold = m_buffers.manifolds[i];
        bool pushes = false;
        for (int k = 0; k < manifold.pointCount; ++k) {
            total.normal += manifold.points[k].normalWork;
            pushes = pushes || manifold.points[k].normalImpulse > 0.0;
        }
        total.friction += manifold.frictionWork;
        m_buffers.pushed[first + i] = pushes ? 1 : 0;
    }
    // gathered here, so that each body's slot is written by the thread that finishes the body
    m_buffers.touching.assign(count, 0);
    for (std::size_t c = 0; c < m_buffers.pushed.size(); ++c) {
        if (m_buffers.pushed[c] == 0) {
            continue;
        }
        const ProxyPair& ends = m_buffers.order.colourEnds[c];
        for (const std::uint32_t side : {ends.a, ends.b}) {
            if (side < count) {
                m_buffers.touching[side] = 1;
            }
        }
    }
    return total;
}

void SoftStep::finish()
{
    // (12.5): the last sub-step's impulses start the next step's sub-steps; a kept island's
    // stay in its lanes, and go to the caches only when its manifolds are built again (12.5b)
    if (!m_kept) {
        collectSoftResults(m_buffers, m_context.threads);
        storeSoftWarmStart(m_island, m_slots, m_buffers.contacts, m_buffers.results,
                           m_buffers.order.colourPosition, m_context.threads,
                           m_buffers.order.colours.halfSplit, m_buffers.centres,
                           m_buffers.startOrientations);
    }
    const IslandWork total = gatherWork();
    // (8.4): the island's kinetic energy and mass, each half summed by the thread that
    // finishes its bodies
    const std::pair<Real, Real> sums = sumOverHalves([&](std::size_t i) {
        return std::pair<Real, Real>{m_buffers.kineticStart[i],
                                     1.0 / m_buffers.bodies[i].invMass};
    });
    const Real kinetic = sums.first;
    const Real mass = sums.second;
    forEachBody([&](std::size_t i) {
        Body& b = body(i);
        const SoftBody& soft = m_buffers.bodies[i];
        const ContactWork work =
            shareOfIslandWork(total, kinetic, mass, m_buffers.bodyWork[i],
                              m_buffers.kineticStart[i], soft.invMass);
        b.position = m_buffers.centres[i] + soft.deltaPosition;
        b.orientation = soft.orientation;
        b.linearVelocity = soft.linearVelocity;
        b.angularVelocity = soft.angularVelocity;
        refreshWorldInertia(b);
        bookContact(b, work, energyOf(b, m_settings.gravity) - m_buffers.energies[i], false);
        m_slots[m_island.bodies[i]].touchingGround = m_buffers.touching[i] != 0;
    });
}

} // namespace tumble
