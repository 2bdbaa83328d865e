// A split island's sub-steps and restitution in one parallel region (docs/physics/
// 12-soft-step.md, (12.9)): each thread books and moves its half's bodies and sweeps its half's
// colours, the threads meeting at a spinning barrier between passes.
#include "step/soft_island_step.hpp"

#include "dynamics/soft_lanes.hpp"

namespace tumble {

bool SoftStep::substepsInOneTeam() const
{
    const SoftColours& colours = m_buffers.order.colours;
    return m_context.threads > 1 && m_buffers.inLanes && m_buffers.manifolds.empty() &&
           colours.halfColours[0] + colours.halfColours[1] > 0 && colours.halfSplit > 0 &&
           colours.halfSplit < m_island.bodies.size();
}

void SoftStep::substepsInOneTeam(Real h, const SoftSolveSettings& solve, int substeps)
{
    const std::size_t count = m_island.bodies.size();
    const std::size_t split = m_buffers.order.colours.halfSplit;
    m_buffers.kinetic.resize(count);
    std::span<SoftBody> bodies = m_buffers.bodies;
    SoftLanes& lanes = m_buffers.lanes;
    parallelTeam(m_context.threads, [&](const PhaseTeam& team) {
        // each half's bodies on the thread that sweeps its colours, as forEachBody gives them
        const auto [first, last] = splitShare(count, split, team.share(), team.shares());
        // a pass starts with the thread's own half's colours, which touch only its own bodies,
        // so a thread's work on its bodies needs no meeting before the pass; the colours across
        // touch both halves, so each pass ends with one
        for (int s = 0; s < substeps; ++s) {
            for (std::size_t i = first; i < last; ++i) {
                bookBody(i, h, s > 0);
            }
            lanes.warmStart(bodies, team);
            team.sync();
            lanes.solve(bodies, solve, true, team);
            team.sync();
            for (std::size_t i = first; i < last; ++i) {
                advancePose(i, h);
            }
            lanes.solve(bodies, solve, false, team);
            team.sync();
        }
        // the last sub-step's work, restitution (12.6), and its work
        for (std::size_t i = first; i < last; ++i) {
            bookBody(i, 0.0, true);
        }
        lanes.restitute(bodies, m_settings.restitutionThreshold, team);
        team.sync();
        for (std::size_t i = first; i < last; ++i) {
            bookBody(i, 0.0, true);
        }
    });
}

} // namespace tumble
