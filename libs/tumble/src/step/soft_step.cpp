// The soft step (docs/physics/12-soft-step.md): narrow phase and rows once a step, then per
// sub-step gravity, warm start, a biased soft solve, positions, and a relax solve; restitution
// after the last sub-step.
#include "step/soft_step.hpp"

#include "step/soft_island_step.hpp"

#include "body_state.hpp"
#include "dynamics/energy_booking.hpp"
#include "dynamics/soft_contact_solver.hpp"
#include "dynamics/soft_lanes.hpp"
#include "dynamics/solver_point.hpp"
#include "step/island_contacts.hpp"
#include "step/soft_buffers.hpp"
#include "step/soft_contact_order.hpp"
#include "step/soft_island_manifolds.hpp"
#include "step/soft_kept_island.hpp"
#include "step/soft_manifolds.hpp"
#include "step/soft_warm_start.hpp"
#include "step/step_scratch.hpp"
#include "parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

namespace tumble {

namespace {

/// The buffers a thread builds an island's manifolds in; kept by the island afterwards, which
/// gives back the ones it held (keepSoftIsland). Large islands (kLargeIslandPairs) and the rest
/// have a set each: both take turns on a thread within a step (a pyramid and a lone cube), and
/// a large island stepped after a small one in the same vectors would construct again, on the
/// calling thread, every contact and block the small one dropped.
std::unique_ptr<SoftBuffers>& threadBuffers(const CoupledIsland& island)
{
    thread_local std::unique_ptr<SoftBuffers> large = std::make_unique<SoftBuffers>();
    thread_local std::unique_ptr<SoftBuffers> small = std::make_unique<SoftBuffers>();
    return island.pairs.size() >= detail::kLargeIslandPairs ? large : small;
}

} // namespace

void SoftStep::run(Real dt)
{
    const int substeps = std::max(1, m_settings.softSubsteps);
    const Real h = dt / substeps;
    prepare(dt);
    // (12.2): a contact spring gets at least four sub-steps a period; against static geometry
    // it is twice as stiff with half the damping ratio, the same damping coefficient 2 zeta omega
    const Real hertz = std::min(m_settings.softContactHertz, 0.25 / h);
    const Real damping = m_settings.softDampingRatio;
    const SoftSolveSettings solve{makeSoftness(hertz, damping, h),
                                  makeSoftness(2.0 * hertz, 0.5 * damping, h),
                                  1.0 / h, m_settings.softPushSpeed};
    if (substepsInOneTeam()) {
        substepsInOneTeam(h, solve, substeps);
    } else {
        for (int s = 0; s < substeps; ++s) {
            substep(h, solve, s > 0);
        }
        // the last sub-step's work, and the kinetic energies restitution starts from
        bookWorkAndGravity(0.0, true);
        restituteSoft(m_buffers.manifolds, m_buffers.bodies, m_settings.restitutionThreshold,
                      m_buffers.order.colours, m_context.threads,
                      m_buffers.inLanes ? &m_buffers.lanes : nullptr);
        // restitution's work
        bookWorkAndGravity(0.0, true);
    }
    finish();
    ++m_events.statistics.islands;
    m_events.statistics.bodies += m_island.bodies.size();
    m_events.statistics.substeps += static_cast<std::size_t>(substeps);
    m_events.statistics.solves += static_cast<std::size_t>(substeps);
    m_events.statistics.sweeps += 2 * static_cast<std::size_t>(substeps);
}

void SoftStep::prepare(Real dt)
{
    startBodies();
    if (m_kept) {
        restartSoftManifolds(m_buffers, m_context.threads);
    } else {
        buildSoftManifolds(m_island, m_slots, m_context, dt, m_buffers);
    }
    m_events.statistics.contactPoints += m_buffers.points;
}

void SoftStep::startBodies()
{
    const std::size_t count = m_island.bodies.size();
    m_buffers.energies.resize(count);
    m_buffers.kineticStart.resize(count);
    m_buffers.bodyWork.resize(count);
    // the loop below writes every dynamic body whole; the static body is the last
    m_buffers.bodies.resize(count + 1);
    m_buffers.bodies[count] = SoftBody{};
    m_buffers.centres.resize(count);
    m_buffers.frames.resize(count);
    m_buffers.startRotationsT.resize(count);
    m_buffers.startOrientations.resize(count);
    // each body writes only its own entries
    forEachBody([&](std::size_t i) {
        // the exact step's kept constraints do not survive a soft step, nor does what the
        // island's other bodies kept of islands they led
        m_buffers.bodyWork[i] = 0.0;
        BodySlot& slot = m_slots[m_island.bodies[i]];
        slot.kept.release();
        if (i != 0) {
            slot.softKept.release();
        }
        const Body& b = slot.body;
        m_buffers.energies[i] = energyOf(b, m_settings.gravity);
        m_buffers.kineticStart[i] = b.kineticEnergy();
        SoftBody& soft = m_buffers.bodies[i];
        soft = softBodyOf(b);
        m_buffers.frames[i] = inertialFrameOf(b);
        if (m_kept) {
            // (12.5b): the manifolds are anchored at the poses they were built at, so the
            // motion since then is the start of the step's displacement (12.3)
            soft.deltaPosition = b.position - m_buffers.centres[i];
            soft.deltaRotation = glm::mat3_cast(b.orientation) * m_buffers.startRotationsT[i];
        } else {
            m_buffers.centres[i] = b.position;
            m_buffers.startRotationsT[i] = glm::transpose(b.rotation());
            m_buffers.startOrientations[i] = b.orientation;
        }
    });
}

void SoftStep::substep(Real h, const SoftSolveSettings& solve, bool bookLast)
{
    std::vector<SoftBody>& bodies = m_buffers.bodies;
    bookWorkAndGravity(h, bookLast);
    const SoftColours& colours = m_buffers.order.colours;
    const int threads = m_context.threads;
    SoftLanes* lanes = m_buffers.inLanes ? &m_buffers.lanes : nullptr;
    warmStartSoft(m_buffers.manifolds, bodies, colours, threads, lanes);
    solveSoft(m_buffers.manifolds, bodies, solve, true, colours, threads, lanes);
    // (12.4): positions from the solved velocities, the orientation to first order, normalised
    forEachBody([&](std::size_t i) { advancePose(i, h); });
    solveSoft(m_buffers.manifolds, bodies, solve, false, colours, threads, lanes);
}

void SoftStep::advancePose(std::size_t i, Real h)
{
    SoftBody& b = m_buffers.bodies[i];
    b.deltaPosition += h * b.linearVelocity;
    const Quat spin(0.0, b.angularVelocity.x, b.angularVelocity.y, b.angularVelocity.z);
    b.orientation = glm::normalize(b.orientation + (0.5 * h) * (spin * b.orientation));
    b.deltaRotation = glm::mat3_cast(b.orientation) * m_buffers.startRotationsT[i];
}

void SoftStep::bookWorkAndGravity(Real h, bool bookWork)
{
    m_buffers.kinetic.resize(m_island.bodies.size());
    forEachBody([&](std::size_t i) { bookBody(i, h, bookWork); });
}

void SoftStep::bookBody(std::size_t i, Real h, bool bookWork)
{
    SoftBody& soft = m_buffers.bodies[i];
    if (bookWork) {
        m_buffers.bodyWork[i] += kineticEnergyWith(m_buffers.frames[i], soft.linearVelocity,
                                                   soft.angularVelocity) -
                                 m_buffers.kinetic[i];
    }
    if (h > 0.0) {
        soft.linearVelocity += m_settings.gravity * h;
    }
    m_buffers.kinetic[i] =
        kineticEnergyWith(m_buffers.frames[i], soft.linearVelocity, soft.angularVelocity);
}

void advanceSoft(const CoupledIsland& island, std::span<BodySlot> slots,
                 const StepContext& context, Real dt, StepEvents& events)
{
    // (12.5b): an island whose bodies stayed put steps on the manifolds it kept; any other
    // builds them in its thread's buffers (or in those it kept before), and keeps those for the
    // next step only if its bodies stayed put over this one (a moving island's buffers stay the
    // thread's, warm in its caches, for the next island)
    SoftKeptIsland& kept = slots[island.bodies.front()].softKept;
    if (island.keepsSoftManifolds) {
        SoftStep(island, slots, context, events, *kept.buffers, true).run(dt);
        kept.unstored = true;
        ++events.statistics.keptIslands;
        return;
    }
    // an island kept before builds in the buffers it kept (their impulses were stored before
    // any step: World::decideKeptSoftIslands), whose pages are already the process's
    std::unique_ptr<SoftBuffers>& buffers =
        kept.buffers != nullptr ? kept.buffers : threadBuffers(island);
    SoftStep(island, slots, context, events, *buffers, false).run(dt);
    if (std::is_sorted(island.pairs.begin(), island.pairs.end()) &&
        softBodiesStill(*buffers, island.bodies, slots, context.threads)) {
        keepSoftIsland(kept, island, context.edits, buffers);
    } else {
        kept.release();
    }
}

} // namespace tumble
