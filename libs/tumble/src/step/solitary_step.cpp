// The exact step of a body alone with the ground: sub-steps ending at impacts.
#include "step/solitary_step.hpp"

#include "collision/collide_cuboid_plane.hpp"
#include "collision/time_of_impact.hpp"
#include "dynamics/contact_solver.hpp"
#include "dynamics/energy_booking.hpp"
#include "dynamics/integrator.hpp"
#include "step/ground_stages.hpp"
#include "step/substep_bracket.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble {

namespace {

/// A touching vertex approaching faster than this at the start of a sub-step is an impact;
/// slower approach is left to the resting-contact solve, m/s.
constexpr Real kImpactSpeed = 1e-3;
/// The time of impact puts the first vertex within this fraction of the contact tolerance of the
/// plane, so impacts happen at the plane while the tolerance still gathers an edge or a face.
constexpr Real kImpactTolerance = 1e-4;
/// An approaching vertex within this many impact tolerances of the plane has reached it: the
/// search stops at the tolerance, but rounding or a sub-step re-solved after the search (4.3a)
/// can leave the vertex a hair above it (04-detection.md, (4.3b)).
constexpr Real kImpactBand = 2.0;
/// (4.3b): sub-steps in one step; the last one ends the step and drops the body's motion over
/// the rest of it, so sub-steps that keep shrinking cost simulated time instead of sinking.
constexpr int kMaxSubsteps = 32;
/// (4.3b): time-of-impact searches in one sub-step, and in one whole step; once a step has spent
/// them, the sub-step in hand ends the step, so one step costs at most twice the budget.
constexpr int kMaxImpactSearches = 64;
/// (4.3b): advances of the time of impact (one pose each) in one whole step; like the searches,
/// they decide only whether another sub-step starts. The scenarios take at most about 130 a
/// step; a thin body chattering on an edge asked for thousands, each pose up to eight
/// compositions of the exact rotation (2.7a).
constexpr int kMaxStepAdvances = 512;
/// (4.3a) aims the end height of the arriving vertex half way between the impact tolerance (below
/// which the time of impact calls the sub-step crossing) and the impact band (at or below which a
/// clear sub-step ends the search), in impact tolerances.
constexpr Real kBracketAim = 1.5;

std::uint8_t vertexMask(const ContactManifold& manifold)
{
    std::uint8_t mask = 0;
    for (int i = 0; i < manifold.pointCount; ++i) {
        mask = static_cast<std::uint8_t>(mask | (1u << manifold.points[i].vertex));
    }
    return mask;
}

/// Height above the plane of the lowest vertex of the manifold that approaches it.
Real lowestApproachingHeight(const Body& body, const ContactManifold& manifold)
{
    Real lowest = std::numeric_limits<Real>::infinity();
    for (int i = 0; i < manifold.pointCount; ++i) {
        const ContactPoint& point = manifold.points[i];
        if (glm::dot(manifold.normal, body.velocityAt(point.position)) < -kImpactSpeed) {
            lowest = std::min(lowest, -point.penetration);
        }
    }
    return lowest;
}

/// Keeps only the points that do not approach the plane.
void dropApproachingPoints(const Body& body, ContactManifold& manifold)
{
    int kept = 0;
    for (int i = 0; i < manifold.pointCount; ++i) {
        const ContactPoint& point = manifold.points[i];
        if (glm::dot(manifold.normal, body.velocityAt(point.position)) >= -kImpactSpeed) {
            manifold.points[kept++] = point;
        }
    }
    manifold.pointCount = kept;
}

/// (4.5): after an impact found by the time of impact the lowest vertex is at most kImpactBand
/// impact tolerances above the plane: a translation puts it on the plane.
void settleOnPlane(Body& body, const ContactManifold& manifold)
{
    Real lowest = std::numeric_limits<Real>::infinity();
    for (int i = 0; i < manifold.pointCount; ++i) {
        lowest = std::min(lowest, -manifold.points[i].penetration);
    }
    if (lowest > 0.0 && std::isfinite(lowest)) {
        body.position -= lowest * manifold.normal;
    }
}

/// True when no vertex can come within the contact tolerance of the ground during a step of dt,
/// whatever the body's rotation (or when there is no ground).
bool clearOfGroundForStep(const Body& body, const StepContext& context, Real dt)
{
    if (!context.ground) {
        return true;
    }
    const WorldSettings& settings = context.settings;
    // (4.7): no vertex is farther than the half diagonal from the centre, and the centre sinks
    // by at most dt times the larger of its start and end approach speeds (gravity is constant);
    // twice the contact tolerance plus a rounding margin keeps every vertex outside the tolerance
    const Real normalStart = glm::dot(Plane::normal(), body.linearVelocity);
    const Real normalEnd = normalStart + glm::dot(Plane::normal(), settings.gravity) * dt;
    const Real sink = dt * std::max({0.0, -normalStart, -normalEnd});
    const Real radius = glm::length(body.shape.halfExtents());
    const Real centreHeight = glm::dot(Plane::normal(), body.position) - context.ground->height;
    const Real clearance =
        2.0 * settings.contactTolerance + 1e-12 * (radius + std::abs(centreHeight));
    if (centreHeight - radius - sink > clearance) {
        return true;
    }
    // (4.7a): closer in, the lowest vertex lowered by the sink and by the rotation's reach over
    // the step, its turning rate (4.4) times the half diagonal (the heights are cheaper than the
    // rotation's bound, so they are tested first)
    const Real lowest = lowestVertexHeight({body.position, body.orientation},
                                           body.shape.halfExtents(), *context.ground);
    if (!(lowest - sink > clearance)) {
        return false;
    }
    const Real turn = dt * radius *
                      rotationBounds(body.orientation, body.angularVelocity, body.inertiaBody(),
                                     dt, settings.integrator)
                          .total();
    return lowest - turn - sink > clearance;
}

/// (2.2a): the start velocity the position update uses. The mean of the start and end velocities
/// moves the centre exactly in free flight and while sliding; where the ground pushed, the normal
/// part moves with the end velocity it allowed, so a stopped approach adds no potential energy.
Vec3 positionStartVelocity(const Vec3& velocityStart, const Body& body,
                           const ContactManifold& contacts)
{
    bool pushed = false;
    for (int i = 0; i < contacts.pointCount; ++i) {
        pushed |= contacts.points[i].normalImpulse > 0.0;
    }
    if (!pushed) {
        return velocityStart;
    }
    const Vec3& n = contacts.normal;
    return velocityStart + glm::dot(n, body.linearVelocity - velocityStart) * n;
}

/// (4.6): a vertex that pushed on the ground ends the sub-step with zero normal velocity, but the
/// position update is exact only to second order: the lowest of them is brought back down, a
/// translation like (4.5) that leaves the velocity alone.
void keepLoadBearingOnPlane(Body& body, const ContactManifold& contacts,
                            const StepContext& context)
{
    if (!context.ground) {
        return;
    }
    const std::array<Real, 8> heights = vertexHeights({body.position, body.orientation},
                                                      body.shape.halfExtents(), *context.ground);
    Real lowest = std::numeric_limits<Real>::infinity();
    for (int i = 0; i < contacts.pointCount; ++i) {
        if (contacts.points[i].normalImpulse > 0.0) {
            lowest = std::min(lowest, heights[contacts.points[i].vertex]);
        }
    }
    if (lowest > 0.0 && lowest <= context.settings.contactTolerance) {
        body.position -= lowest * Plane::normal();
    }
}

/// One body's walk through its sub-steps; the members are what the stages share.
class SolitaryStep {
public:
    SolitaryStep(BodyId id, BodySlot& slot, const StepContext& context, StepEvents& events)
        : m_id(id), m_slot(slot), m_body(slot.body), m_context(context),
          m_settings(context.settings), m_events(events),
          m_solveSettings{m_settings.restitutionThreshold, m_settings.solverIterations},
          m_impactTolerance(kImpactTolerance * m_settings.contactTolerance),
          m_energy(energyOf(m_body, m_settings.gravity))
    {
    }

    void run(Real dt);

private:
    void resolveArrivedImpact(ContactManifold& contacts);
    ContactWork solveVelocities(ContactManifold& contacts, Real tau);
    Real searchSubstep(ContactManifold& contacts, Real tau, ContactWork& restingWork);
    void moveAndCorrect(const ContactManifold& contacts, const ContactWork& restingWork,
                        Real tau);

    BodyId m_id;
    BodySlot& m_slot;
    Body& m_body;
    const StepContext& m_context;
    const WorldSettings& m_settings;
    StepEvents& m_events;
    ContactSolveSettings m_solveSettings;
    Real m_impactTolerance;
    /// The body's energy now, carried from stage to stage: each booking's "after" is the next
    /// one's "before".
    Real m_energy;
    Real m_elapsed = 0.0;
    int m_searches = 0;
    int m_advances = 0;
    /// Velocities at the start of the sub-step's velocity stage.
    Vec3 m_velocityStart{0.0};
    Vec3 m_angularVelocityStart{0.0};
};

void SolitaryStep::run(Real dt)
{
    for (int substep = 0;; ++substep) {
        const Real remaining = dt - m_elapsed;
        // 1. detect the vertices touching the ground now
        ContactManifold contacts = groundContacts(m_id, m_body, m_context);
        // 2. resolve an impact at once when an approaching vertex has reached the plane
        resolveArrivedImpact(contacts);
        // 3. integrate velocities over the rest of the step: gravity, then resting contact
        m_velocityStart = m_body.linearVelocity;
        m_angularVelocityStart = m_body.angularVelocity;
        ContactWork restingWork = solveVelocities(contacts, remaining);
        // 4. shorten the sub-step to the first impact of another vertex (4.3), (4.3a)
        const Real tau = searchSubstep(contacts, remaining, restingWork);
        m_slot.warmStart = makeWarmStart(contacts, tau);
        recordContacts(ContactPhase::Resting, contacts, m_body, m_context.time + m_elapsed,
                       m_settings, m_events);
        // 5. integrate positions; 6. corrections (4.6), (4.5)
        moveAndCorrect(contacts, restingWork, tau);
        // (not "tau == remaining": with a NaN state that never holds and the step never ended)
        if (!(tau < remaining)) {
            break;
        }
        m_elapsed += tau;
        // elapsed + tau can round up to dt when tau falls short of the remaining time by less
        // than an ulp: the step is then complete
        if (!(m_elapsed < dt)) {
            break;
        }
        // (4.3b): the last sub-step allowed, or one that spent the step's searches or advances,
        // ends it
        if (substep + 1 >= kMaxSubsteps || m_searches >= kMaxImpactSearches ||
            m_advances >= kMaxStepAdvances) {
            break;
        }
    }
    // the predicate of detection (4.1) without building the manifold
    m_slot.touchingGround =
        m_context.ground && lowestVertexHeight({m_body.position, m_body.orientation},
                                               m_body.shape.halfExtents(),
                                               *m_context.ground) <= m_settings.contactTolerance;
}

void SolitaryStep::resolveArrivedImpact(ContactManifold& contacts)
{
    // approaching vertices still above the impact band are left to the time of impact, so the
    // impact happens at the plane
    if (!(approachSpeed(m_body, contacts) > kImpactSpeed)) {
        return;
    }
    if (!(lowestApproachingHeight(m_body, contacts) <= kImpactBand * m_impactTolerance)) {
        dropApproachingPoints(m_body, contacts);
        return;
    }
    const ImpactOutcome outcome = resolveImpact(m_body, contacts, m_solveSettings);
    const Real energyAfterImpact = energyOf(m_body, m_settings.gravity);
    bookContact(m_body, outcome.work, energyAfterImpact - m_energy, true);
    const Real time = m_context.time + m_elapsed;
    recordImpact(contacts, outcome, time, m_events);
    recordContacts(ContactPhase::Impact, contacts, m_body, time, m_settings, m_events);
    settleOnPlane(m_body, contacts);
    m_energy = bookCorrection(m_body, energyAfterImpact, m_settings.gravity);
}

ContactWork SolitaryStep::solveVelocities(ContactManifold& contacts, Real tau)
{
    return solveRestingContact(m_body, contacts, m_settings.gravity * tau, tau, m_solveSettings,
                               m_slot.warmStart);
}

Real SolitaryStep::searchSubstep(ContactManifold& contacts, Real tau, ContactWork& restingWork)
{
    // The resting solve depends on tau, so the motion over a shortened sub-step is not the one
    // searched: search again until no vertex crosses within it, keeping the bracket of (4.3a)
    // when the re-solved motion no longer comes near the plane.
    if (!m_context.ground) {
        return tau;
    }
    const Plane& ground = *m_context.ground;
    const std::uint8_t touching = vertexMask(contacts);
    const Vec3 halfExtents = m_body.shape.halfExtents();
    const Real aim = kBracketAim * m_impactTolerance;
    SubstepBracket bracket;
    for (int search = 0; search < kMaxImpactSearches; ++search) {
        ++m_searches;
        SubstepMotion motion;
        motion.start = {m_body.position, m_body.orientation};
        const Vec3 velocityStart = positionStartVelocity(m_velocityStart, m_body, contacts);
        // semi-implicit Euler for the handout integrator: the end velocity for the whole sub-step
        motion.velocityStart =
            m_settings.integrator == Integrator::Exact ? velocityStart : m_body.linearVelocity;
        motion.velocityEnd = m_body.linearVelocity;
        motion.angularVelocity = m_body.angularVelocity;
        motion.inertiaBody = m_body.inertiaBody();
        motion.tau = tau;
        motion.integrator = m_settings.integrator;
        const Real impact = timeOfImpact(motion, halfExtents, ground, touching, m_impactTolerance,
                                         m_advances);
        Real next = 0.0;
        if (impact >= tau) {
            // done when nothing crossed, when the vertex found ends the sub-step within the
            // impact band (met next sub-step), or when the bracket is closed
            if (!bracket.hasCrossing()) {
                return tau;
            }
            const Real endHeight = freeClearance(motion, halfExtents, ground, touching, tau);
            bracket.markClear(tau, endHeight - aim);
            if (endHeight <= kImpactBand * m_impactTolerance || bracket.closed()) {
                return tau;
            }
            next = bracket.next();
        } else if (freeClearance(motion, halfExtents, ground, touching, impact) >
                   m_impactTolerance) {
            // the search ran out of advances before any vertex arrived (one grazes the plane):
            // the motion is only known clear until then; a longer sub-step known clear wins
            if (bracket.clear() > 0.0) {
                break;
            }
            next = impact;
        } else {
            bracket.markCrossing(tau,
                                 freeClearance(motion, halfExtents, ground, touching, tau) - aim);
            next = bracket.clear() > 0.0 ? bracket.next() : impact;
        }
        m_body.linearVelocity = m_velocityStart;
        m_body.angularVelocity = m_angularVelocityStart;
        tau = next;
        restingWork = solveVelocities(contacts, tau);
    }
    if (bracket.clear() > 0.0) {
        m_body.linearVelocity = m_velocityStart;
        m_body.angularVelocity = m_angularVelocityStart;
        tau = bracket.clear();
        restingWork = solveVelocities(contacts, tau);
    }
    return tau;
}

void SolitaryStep::moveAndCorrect(const ContactManifold& contacts, const ContactWork& restingWork,
                                  Real tau)
{
    const Real energyStart = m_energy;
    integratePositions(m_body, positionStartVelocity(m_velocityStart, m_body, contacts), tau,
                       m_settings.integrator);
    const Real energyAfterMotion = energyOf(m_body, m_settings.gravity);
    bookContact(m_body, restingWork, energyAfterMotion - energyStart, false);
    keepLoadBearingOnPlane(m_body, contacts, m_context);
    correctPenetration(m_body, m_context.ground);
    m_energy = bookCorrection(m_body, energyAfterMotion, m_settings.gravity);
}

} // namespace

void advanceSolitary(BodyId id, BodySlot& slot, const StepContext& context, Real dt,
                     StepEvents& events)
{
    if (clearOfGroundForStep(slot.body, context, dt)) {
        // the stages of a sub-step for a body that touches nothing, the same operations in the
        // same order: gravity, then the position and rotation over the step
        moveFreely(slot.body, dt, context.settings);
        slot.warmStart.vertices = 0;
        slot.touchingGround = false;
        return;
    }
    SolitaryStep(id, slot, context, events).run(dt);
}

} // namespace tumble
