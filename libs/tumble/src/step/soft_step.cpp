// The soft step (docs/physics/12-soft-step.md): narrow phase and rows once a step, then per
// sub-step gravity, warm start, a biased soft solve, positions, and a relax solve; restitution
// after the last sub-step.
#include "step/soft_step.hpp"

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
#include "parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

namespace tumble {

namespace {

/// The buffers a thread builds an island's manifolds in; kept by the island afterwards, which
/// gives back the ones it held (keepSoftIsland).
std::unique_ptr<SoftBuffers>& threadBuffers()
{
    thread_local std::unique_ptr<SoftBuffers> buffers = std::make_unique<SoftBuffers>();
    return buffers;
}

class SoftStep {
public:
    /// With `kept`, `buffers` hold the island's manifolds of its last step (12.5b).
    SoftStep(const CoupledIsland& island, std::span<BodySlot> slots, const StepContext& context,
             StepEvents& events, SoftBuffers& buffers, bool kept)
        : m_island(island), m_slots(slots), m_context(context), m_settings(context.settings),
          m_events(events), m_buffers(buffers), m_kept(kept)
    {
    }

    void run(Real dt);

private:
    void prepare(Real dt);
    /// Each body's start of the step; a kept island's bodies start where they moved to since
    /// its manifolds were built (12.5b).
    void startBodies();
    /// The work of the island's impulses over the step, in a fixed order (the lanes' blocks,
    /// then the manifolds not packed), and in `m_buffers.touching` each body one of whose
    /// points pushed in the last sub-step (7.1).
    IslandWork gatherWork();
    /// One sub-step; `bookLast` when a sub-step went before it (its work is booked here).
    void substep(Real h, const SoftSolveSettings& solve, bool bookLast);
    void finish();
    /// For each body, in one pass: with `bookWork`, adds to its work what its kinetic energy
    /// gained since `m_buffers.kinetic` (the passes' work since the last call); then gravity
    /// over h (none for h = 0); then keeps its kinetic energy in `m_buffers.kinetic`.
    void bookWorkAndGravity(Real h, bool bookWork);
    /// bookWorkAndGravity's work for body i.
    void bookBody(std::size_t i, Real h, bool bookWork);
    /// (12.4): body i's position and orientation advanced over h with its solved velocities.
    void advancePose(std::size_t i, Real h);
    /// Whether the sub-steps run in one parallel region (substepsInOneTeam): an island split
    /// in halves (12.9), all of its manifolds in lanes, on several threads.
    [[nodiscard]] bool substepsInOneTeam() const;
    /// The sub-steps of substep and the restitution after them, every pass in one parallel
    /// region, each thread sweeping its half's bodies and colours, the threads meeting at a
    /// spinning barrier between passes: the same passes in the same order, so the same bits.
    void substepsInOneTeam(Real h, const SoftSolveSettings& solve, int substeps);
    Body& body(std::size_t local) { return m_slots[m_island.bodies[local]].body; }
    /// visit(i) for each of the island's bodies, each half of a split island on the thread that
    /// sweeps its colours (12.9); each call writes only body i's entries.
    template <typename Visit>
    void forEachBody(const Visit& visit)
    {
        parallelForSplit(m_island.bodies.size(), m_buffers.order.colours.halfSplit,
                         m_context.threads, visit);
    }

    const CoupledIsland& m_island;
    std::span<BodySlot> m_slots;
    const StepContext& m_context;
    const WorldSettings& m_settings;
    StepEvents& m_events;
    SoftBuffers& m_buffers;
    bool m_kept;
};

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
    m_buffers.bodyWork.assign(count, 0.0);
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
        const std::size_t share = team.share();
        const std::size_t first = share == 0 ? 0 : share == 1 ? split : count;
        const std::size_t last = share == 0 && team.shares() > 1 ? split : count;
        for (int s = 0; s < substeps; ++s) {
            for (std::size_t i = first; i < last; ++i) {
                bookBody(i, h, s > 0);
            }
            team.sync();
            lanes.warmStart(bodies, team);
            team.sync();
            lanes.solve(bodies, solve, true, team);
            team.sync();
            for (std::size_t i = first; i < last; ++i) {
                advancePose(i, h);
            }
            team.sync();
            lanes.solve(bodies, solve, false, team);
            team.sync();
        }
        // the last sub-step's work, restitution (12.6), and its work
        for (std::size_t i = first; i < last; ++i) {
            bookBody(i, 0.0, true);
        }
        team.sync();
        lanes.restitute(bodies, m_settings.restitutionThreshold, team);
        team.sync();
        for (std::size_t i = first; i < last; ++i) {
            bookBody(i, 0.0, true);
        }
    });
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

void SoftStep::finish()
{
    const std::size_t count = m_island.bodies.size();
    // (12.5): the last sub-step's impulses start the next step's sub-steps; a kept island's
    // stay in its lanes, and go to the caches only when its manifolds are built again (12.5b)
    if (!m_kept) {
        collectSoftResults(m_buffers, m_context.threads);
        storeSoftWarmStart(m_island, m_slots, m_buffers.contacts, m_buffers.results,
                           m_buffers.order.colourPosition, m_context.threads, m_buffers.centres,
                           m_buffers.startOrientations);
    }
    const IslandWork total = gatherWork();
    std::vector<SolverBody>& inverse = m_buffers.inverseMasses;
    inverse.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        inverse[i].invMass = m_buffers.bodies[i].invMass;
    }
    const std::vector<ContactWork> work =
        shareIslandWork(total, m_buffers.bodyWork, m_buffers.kineticStart, inverse);
    forEachBody([&](std::size_t i) {
        Body& b = body(i);
        const SoftBody& soft = m_buffers.bodies[i];
        b.position = m_buffers.centres[i] + soft.deltaPosition;
        b.orientation = soft.orientation;
        b.linearVelocity = soft.linearVelocity;
        b.angularVelocity = soft.angularVelocity;
        refreshWorldInertia(b);
        bookContact(b, work[i], energyOf(b, m_settings.gravity) - m_buffers.energies[i], false);
        m_slots[m_island.bodies[i]].touchingGround = m_buffers.touching[i] != 0;
    });
}

} // namespace

void advanceSoft(const CoupledIsland& island, std::span<BodySlot> slots,
                 const StepContext& context, Real dt, StepEvents& events)
{
    // (12.5b): an island whose bodies stayed put steps on the manifolds it kept; any other
    // builds them in its thread's buffers, and keeps those for the next step only if its
    // bodies stayed put over this one (a moving island's buffers stay the thread's, warm in
    // its caches, for the next island)
    SoftKeptIsland& kept = slots[island.bodies.front()].softKept;
    if (island.keepsSoftManifolds) {
        SoftStep(island, slots, context, events, *kept.buffers, true).run(dt);
        kept.unstored = true;
        ++events.statistics.keptIslands;
        return;
    }
    std::unique_ptr<SoftBuffers>& buffers = threadBuffers();
    SoftStep(island, slots, context, events, *buffers, false).run(dt);
    if (std::is_sorted(island.pairs.begin(), island.pairs.end()) &&
        softBodiesStill(*buffers, island.bodies, slots, context.threads)) {
        keepSoftIsland(kept, island, context.edits, buffers);
    } else {
        kept.release();
    }
}

} // namespace tumble
