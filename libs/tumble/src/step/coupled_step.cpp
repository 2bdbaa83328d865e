// An island of touching bodies: sub-steps that end at the next impact, so impacts are resolved
// one after the other in time order (docs/physics/11-island-solver.md).
#include "step/coupled_step.hpp"

#include "dynamics/energy_booking.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/island_solver.hpp"
#include "parallel_for.hpp"
#include "step/arrivals.hpp"
#include "step/contact_colour_order.hpp"
#include "step/island_constraints.hpp"
#include "step/island_contacts.hpp"
#include "step/island_events.hpp"
#include "step/island_motion.hpp"
#include "step/kept_constraints.hpp"

#include <algorithm>
#include <cmath>

namespace tumble {

namespace {

/// A touching point approaching faster than this is an impact, m/s (as for a body alone).
constexpr Real kImpactSpeed = 1e-3;
/// Sub-steps in one step; the last one takes the rest of the step whatever arrives in it, and
/// the speculative targets (11.4) still keep its points from crossing.
constexpr int kMaxSubsteps = 16;
/// Re-solves of one sub-step cut at an arrival (11.8).
constexpr int kMaxArrivalCuts = 4;
/// Convergence of the sweeps (5.10): impacts to rounding, resting contact tighter than for a body
/// alone, since what is left undone stays in the velocities of a whole stack (11.5).
constexpr Real kImpactConvergence = 1e-13;
constexpr Real kRestingConvergence = 1e-12;
/// (11.5a): a resting solve also ends when a sweep corrects no point's velocity by more than
/// this share of the speed gravity gives in the sub-step, |g| tau: the impulses may still creep
/// along the many equal ways of carrying a statically indeterminate load, but the motion does
/// not change.
constexpr Real kRestingVelocityShare = 1e-10;

/// The vectors of an island's step. Each thread keeps one set from island to island and step to
/// step, so that no stage has the system map and zero fresh memory every step. The constraints
/// (14 MB for Jolt's pyramid) are the island's own, kept by its lowest body (11.6a).
struct IslandBuffers {
    std::vector<SolverBody> bodies;
    std::vector<IslandContact> contacts;
    std::vector<IslandContact> spareContacts;
    SweepSchedule schedule;
    BodyConstraintLists constraintsOf;
    std::vector<Real> energies;
    std::vector<Vec3> velocityStart;
    std::vector<Vec3> angularVelocityStart;
    std::vector<GapMotion> gapMotions;
};

IslandBuffers& threadBuffers()
{
    thread_local IslandBuffers buffers;
    return buffers;
}

class CoupledStep {
public:
    CoupledStep(const CoupledIsland& island, std::span<BodySlot> slots, const StepContext& context,
                StepEvents& events, IslandBuffers& buffers)
        : m_island(island), m_slots(slots), m_context(context), m_settings(context.settings),
          m_events(events), m_bodies(buffers.bodies), m_contacts(buffers.contacts),
          m_spareContacts(buffers.spareContacts), m_kept(slots[island.bodies.front()].kept),
          m_constraints(m_kept.constraints), m_schedule(buffers.schedule),
          m_constraintsOf(buffers.constraintsOf),
          m_energies(buffers.energies), m_velocityStart(buffers.velocityStart),
          m_angularVelocityStart(buffers.angularVelocityStart), m_gapMotions(buffers.gapMotions)
    {
    }

    void run(Real dt);

private:
    void gatherBodies();
    void prepareConstraints(int substep);
    void resolveImpacts(Real time);
    [[nodiscard]] std::vector<ContactConstraint> impactConstraints() const;
    void solveSubstep(Real tau);
    [[nodiscard]] Real earliestArrival(Real tau);
    void finishSubstep(Real tau);
    Body& body(std::size_t local) { return m_slots[m_island.bodies[local]].body; }
    [[nodiscard]] Real restingVelocityTolerance(Real tau) const
    {
        return kRestingVelocityShare * glm::length(m_settings.gravity) * tau;
    }
    /// Each body's kinetic energy in m_bodies less `kineticStart`: the work the contact
    /// impulses did on it since the solve started (8.2).
    [[nodiscard]] std::vector<Real> bodyWork(std::span<const Real> kineticStart)
    {
        std::vector<Real> work(kineticStart.size());
        parallelFor(work.size(), m_context.threads, [&](std::size_t i) {
            work[i] = kineticEnergyWith(body(i), m_bodies[i].linearVelocity,
                                        m_bodies[i].angularVelocity) -
                      kineticStart[i];
        });
        return work;
    }
    void countSolve(int sweeps)
    {
        ++m_events.statistics.solves;
        m_events.statistics.sweeps += static_cast<std::size_t>(sweeps);
    }

    const CoupledIsland& m_island;
    std::span<BodySlot> m_slots;
    const StepContext& m_context;
    const WorldSettings& m_settings;
    StepEvents& m_events;
    std::vector<SolverBody>& m_bodies;
    std::vector<IslandContact>& m_contacts;
    std::vector<IslandContact>& m_spareContacts;
    /// The island's constraints as its lowest body keeps them from step to step (11.6a).
    KeptConstraints& m_kept;
    std::vector<ContactConstraint>& m_constraints;
    /// Whether the next solve starts from the kept constraints' impulses rather than the cached
    /// ones (11.6a).
    bool m_startFromKept = false;
    /// The order of the sweeps over m_constraints (11.5c), made once a sub-step.
    SweepSchedule& m_schedule;
    BodyConstraintLists& m_constraintsOf;
    /// Each body's energy now, carried from stage to stage (8.3).
    std::vector<Real>& m_energies;
    std::vector<Vec3>& m_velocityStart;
    std::vector<Vec3>& m_angularVelocityStart;
    /// Each constraint's gap motion over the last solve of the current sub-step (11.8).
    std::vector<GapMotion>& m_gapMotions;
    /// Time into the step at which the current sub-step starts, s.
    Real m_elapsed = 0.0;
};

void CoupledStep::gatherBodies()
{
    const std::size_t count = m_island.bodies.size();
    m_bodies.assign(count + 1, SolverBody{});
    for (std::size_t i = 0; i < count; ++i) {
        m_bodies[i] = solverBodyOf(body(i));
    }
}

void CoupledStep::run(Real dt)
{
    const std::size_t count = m_island.bodies.size();
    m_energies.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        m_energies[i] = energyOf(body(i), m_settings.gravity);
    }
    ++m_events.statistics.islands;
    m_events.statistics.bodies += count;
    for (int substep = 0;; ++substep) {
        const Real remaining = dt - m_elapsed;
        // narrow phase: every point within reach of the rest of the step
        findIslandContacts(m_island, m_slots, m_context, remaining, false, m_contacts);
        orderContactsByColour(m_contacts, count + 1, m_spareContacts, m_context.threads);
        prepareConstraints(substep);
        m_gapMotions.clear();
        ++m_events.statistics.substeps;
        if (substep == 0) {
            m_events.statistics.contactPoints += m_constraints.size();
        }
        // impacts of the points in contact now, all together (11.4)
        resolveImpacts(m_context.time + m_elapsed);
        // velocities over the rest of the step, shortened to the next impact (11.8)
        Real tau = remaining;
        solveSubstep(tau);
        // the re-solved motion is only linear in time to first order (rotation), so a point can
        // still arrive inside the shortened sub-step: cut again, a few times at most
        for (int cut = 0; cut < kMaxArrivalCuts && substep + 1 < kMaxSubsteps; ++cut) {
            const Real arrival = earliestArrival(tau);
            if (!(arrival < tau)) {
                break;
            }
            tau = arrival;
            solveSubstep(tau);
        }
        // positions, push-out, warm start (11.9), (11.10)
        finishSubstep(tau);
        if (!(tau < remaining)) {
            // (11.6a): a step of one sub-step leaves its constraints for the next
            m_kept.valid = substep == 0;
            m_kept.tau = tau;
            break;
        }
        m_elapsed += tau;
        if (!(m_elapsed < dt)) {
            break;
        }
    }
}

void CoupledStep::prepareConstraints(int substep)
{
    // the island's other bodies keep no constraints: those of islands they led are gone
    for (std::size_t i = 1; i < m_island.bodies.size(); ++i) {
        m_slots[m_island.bodies[i]].kept.release();
    }
    // (11.6a): the first sub-step of an island whose contacts and bodies have not moved since
    // the last step keeps its constraints
    m_startFromKept = substep == 0 && keptConstraintsHold(m_kept, m_island, m_slots, m_contacts,
                                                          m_context.threads);
    if (m_startFromKept) {
        refreshKeptConstraints(m_kept, m_contacts, m_context.threads);
        ++m_events.statistics.keptIslands;
        return;
    }
    m_kept.valid = false;
    buildConstraints(m_contacts, m_slots, m_island, m_constraints, m_context.threads);
    if (substep == 0) {
        recordKeptInputs(m_kept, m_island, m_slots, m_contacts, m_context.threads);
    }
}

void CoupledStep::resolveImpacts(Real time)
{
    const Real touching = m_settings.contactTolerance;
    gatherBodies();
    const bool approaching =
        parallelAnyOf(m_constraints.size(), m_context.threads, [&](std::size_t k) {
            const ContactConstraint& c = m_constraints[k];
            const Vec3 velocity = m_bodies[c.bodyB].velocityAt(c.offsetB) -
                                  m_bodies[c.bodyA].velocityAt(c.offsetA);
            return c.separation <= touching && glm::dot(c.normal, velocity) < -kImpactSpeed;
        });
    if (!approaching) {
        return;
    }
    std::vector<ContactConstraint> impact = impactConstraints();
    std::vector<Real> kineticBefore(m_island.bodies.size());
    for (std::size_t i = 0; i < m_island.bodies.size(); ++i) {
        kineticBefore[i] = body(i).kineticEnergy();
    }
    // (11.4a) Poisson's restitution: compression until no point approaches, each point's
    // restitution share e lambda_c of its compression impulse, and a plastic pass over any point
    // that share left approaching; with no share (e = 0) nothing is left to pass over
    countSolve(
        solveConstraints(impact, m_bodies, m_settings.solverIterations, kImpactConvergence, 0.0,
                         m_context.threads));
    if (applyRestitution(impact, m_bodies)) {
        std::vector<ContactConstraint> correction = impact;
        for (ContactConstraint& c : correction) {
            c.normalImpulse = 0.0;
            c.tangentImpulse1 = 0.0;
            c.tangentImpulse2 = 0.0;
            c.frictionShift = 0.0;
            c.normalWork = 0.0;
            c.frictionWork = 0.0;
        }
        countSolve(solveConstraints(correction, m_bodies, m_settings.solverIterations,
                                    kImpactConvergence, 0.0, m_context.threads));
        for (std::size_t k = 0; k < impact.size(); ++k) {
            impact[k].normalImpulse += correction[k].normalImpulse;
            impact[k].tangentImpulse1 += correction[k].tangentImpulse1;
            impact[k].tangentImpulse2 += correction[k].tangentImpulse2;
            impact[k].normalWork += correction[k].normalWork;
            impact[k].frictionWork += correction[k].frictionWork;
        }
    }
    const std::vector<ContactWork> work =
        shareIslandWork(sumPointWork(impact, m_context.threads), bodyWork(kineticBefore),
                        kineticBefore, m_bodies);
    for (std::size_t i = 0; i < m_island.bodies.size(); ++i) {
        Body& b = body(i);
        b.linearVelocity = m_bodies[i].linearVelocity;
        b.angularVelocity = m_bodies[i].angularVelocity;
        const Real energyAfter = energyOf(b, m_settings.gravity);
        bookContact(b, work[i],
                    energyAfter - m_energies[i], true);
        m_energies[i] = energyAfter;
    }
    recordIslandImpacts(m_island, m_slots, m_contacts, impact, m_bodies, kineticBefore,
                        kImpactSpeed, time, m_events);
    if (m_settings.recordContacts) {
        recordIslandContacts(ContactPhase::Impact, m_island, m_slots, m_contacts, impact,
                             m_bodies, kineticBefore, m_settings.contactTolerance, time,
                             m_events);
    }
}

std::vector<ContactConstraint> CoupledStep::impactConstraints() const
{
    // the points in contact only: those still apart are met at their own time; every target is
    // no approach, and the restitution follows the compression (11.4a)
    const Real touching = m_settings.contactTolerance;
    std::vector<ContactConstraint> impact;
    impact.reserve(m_constraints.size());
    for (const ContactConstraint& c : m_constraints) {
        if (c.separation <= touching) {
            ContactConstraint& prepared = impact.emplace_back(c);
            prepareConstraintTargets(prepared, m_bodies,
                                     {ConstraintTarget::Impact, 0.0, touching,
                                      m_settings.restitutionThreshold});
            prepared.targetNormalVelocity = 0.0;
            // the impacts start from no impulse, whatever the constraints hold (11.6a)
            prepared.normalImpulse = 0.0;
            prepared.tangentImpulse1 = 0.0;
            prepared.tangentImpulse2 = 0.0;
            prepared.frictionShift = 0.0;
        }
    }
    return impact;
}

void CoupledStep::solveSubstep(Real tau)
{
    gatherBodies();
    const std::size_t count = m_island.bodies.size();
    m_velocityStart.resize(count);
    m_angularVelocityStart.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        m_velocityStart[i] = m_bodies[i].linearVelocity;
        m_angularVelocityStart[i] = m_bodies[i].angularVelocity;
        // gravity over the sub-step (2.2)
        m_bodies[i].linearVelocity += m_settings.gravity * tau;
    }
    const ConstraintTargetSettings targets{ConstraintTarget::Substep, tau,
                                           m_settings.contactTolerance,
                                           m_settings.restitutionThreshold};
    prepareConstraintTargets(m_constraints, m_bodies, targets, m_context.threads);
    keepExactArrivals(m_constraints, m_gapMotions, tau, m_settings.contactTolerance,
                      m_context.threads);
    scheduleSweeps(m_constraints, m_bodies, m_schedule);
    if (m_startFromKept) {
        // (11.6a): the kept impulses, scaled down to a shorter sub-step, never up, as they apply
        warmStartScaled(m_constraints, m_bodies, m_schedule, std::min(1.0, tau / m_kept.tau),
                        m_context.threads);
        m_startFromKept = false;
    } else {
        loadWarmStart(m_island, m_slots, m_contacts, m_constraints, tau, m_settings,
                      m_context.threads);
        warmStart(m_constraints, m_bodies, m_schedule, m_context.threads);
    }
    countSolve(solveConstraints(m_constraints, m_bodies, m_schedule,
                                m_settings.solverIterations, kRestingConvergence,
                                restingVelocityTolerance(tau), m_context.threads));
}

Real CoupledStep::earliestArrival(Real tau)
{
    // (11.8): a point still apart that the solve had to stop (its speculative target bound) and
    // that arrives fast enough to bounce ends the sub-step when it arrives, so its impact is
    // resolved at contact, before the impacts that come after it
    const Real touching = m_settings.contactTolerance;
    if (!anyBouncingArrival(m_constraints, touching, m_context.threads)) {
        return tau;
    }
    // the motion without the points still apart: the points in contact solved alone, from the
    // start velocities and gravity, give each gap its free acceleration
    std::vector<SolverBody> free(m_bodies);
    for (std::size_t i = 0; i < m_velocityStart.size(); ++i) {
        free[i].linearVelocity = m_velocityStart[i] + m_settings.gravity * tau;
        free[i].angularVelocity = m_angularVelocityStart[i];
    }
    std::vector<ContactConstraint> inContact;
    for (const ContactConstraint& c : m_constraints) {
        if (c.separation <= touching) {
            inContact.push_back(c);
        }
    }
    warmStart(inContact, free);
    solveConstraints(inContact, free, m_settings.solverIterations, kRestingConvergence,
                     restingVelocityTolerance(tau), m_context.threads);
    gapMotions(m_constraints, free, m_velocityStart, m_angularVelocityStart, tau, m_gapMotions);
    return tumble::earliestArrival(m_constraints, m_gapMotions, tau, touching,
                                   m_settings.restitutionThreshold);
}

void CoupledStep::finishSubstep(Real tau)
{
    const std::size_t count = m_island.bodies.size();
    std::vector<Real> kineticBefore(count);
    for (std::size_t i = 0; i < count; ++i) {
        kineticBefore[i] = body(i).kineticEnergy();
    }
    // the impulses' work on each body: its kinetic energy now less at the solve's start, after
    // gravity's push over the sub-step (2.2)
    std::vector<Real> kineticStart(count);
    parallelFor(count, m_context.threads, [&](std::size_t i) {
        kineticStart[i] =
            kineticEnergyWith(body(i), m_velocityStart[i] + m_settings.gravity * tau,
                              m_angularVelocityStart[i]);
    });
    const std::vector<ContactWork> work =
        shareIslandWork(sumPointWork(m_constraints, m_context.threads), bodyWork(kineticStart),
                        kineticBefore, m_bodies);
    m_constraintsOf.build(m_constraints, count, m_context.threads);
    // each body reads its own constraints and writes only itself
    const auto advance = [&](std::size_t i) {
        Body& b = body(i);
        b.linearVelocity = m_bodies[i].linearVelocity;
        b.angularVelocity = m_bodies[i].angularVelocity;
        integrateIslandBody(b, m_velocityStart[i], m_constraints, m_constraintsOf.of(i), tau,
                            m_settings.integrator);
        const Real energyAfter = energyOf(b, m_settings.gravity);
        bookContact(b, work[i], energyAfter - m_energies[i], false);
        m_energies[i] = energyAfter;
    };
    parallelFor(count, m_context.threads, advance);
    storeWarmStart(m_island, m_slots, m_contacts, m_constraints, tau, m_context.threads);
    if (m_settings.recordContacts) {
        recordIslandContacts(ContactPhase::Resting, m_island, m_slots, m_contacts, m_constraints,
                             m_bodies, kineticBefore, m_settings.contactTolerance,
                             m_context.time + m_elapsed, m_events);
    }
    pushOutOfPenetration(m_island, m_slots, m_constraints, tau, m_settings, m_context.threads);
    for (std::size_t i = 0; i < count; ++i) {
        m_energies[i] = bookCorrection(body(i), m_energies[i], m_settings.gravity);
    }
    markTouching(m_island, m_slots, m_constraints, m_constraintsOf, m_settings.contactTolerance,
                 m_context.threads);
}

} // namespace

void advanceCoupled(const CoupledIsland& island, std::span<BodySlot> slots,
                    const StepContext& context, Real dt, StepEvents& events)
{
    CoupledStep(island, slots, context, events, threadBuffers()).run(dt);
}

} // namespace tumble
