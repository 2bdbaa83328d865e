// World: body storage behind ids, the setters that keep bodies consistent, and the step.
#include "tumble/world.hpp"

#include "body_state.hpp"
#include "collision/collide_cuboid_plane.hpp"
#include "collision/time_of_impact.hpp"
#include "dynamics/contact_solver.hpp"
#include "dynamics/integrator.hpp"
#include "tumble_assert.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <thread>

#ifdef TUMBLE_HAVE_OPENMP
#include <omp.h>
#endif

namespace tumble {

namespace {

/// A touching vertex approaching faster than this at the start of a sub-step is an impact;
/// slower approach is left to the resting-contact solve, m/s.
constexpr Real kImpactSpeed = 1e-3;
/// The time of impact puts the first vertex within this fraction of the contact tolerance of the
/// plane, so impacts happen at the plane while the tolerance still gathers an edge or a face.
constexpr Real kImpactTolerance = 1e-4;
/// An approaching vertex within this many impact tolerances of the plane has reached it: the
/// search stops at the tolerance, but rounding (a 500 m lever) or a sub-step re-solved after the
/// search (4.3a) can leave the vertex a hair above it, and waiting for it to cross the tolerance
/// exactly took ever shorter sub-steps (04-detection.md, (4.3b)).
constexpr Real kImpactBand = 2.0;
/// Sub-steps in one step: the last one is searched like the others but ends the step, and the
/// body's motion over the rest of the step is dropped, so a pathological case (sub-steps that
/// keep shrinking) costs simulated time instead of sinking and the push-out's energy (4.3b).
constexpr int kMaxSubsteps = 32;
/// Time-of-impact searches in one sub-step: each searches the motion re-solved for the shorter
/// sub-step the previous one found (the fixed point is usually reached in a few, a bisection
/// (4.3a) in about 20). The same number bounds the searches of a whole step: each costs a
/// contact solve, so once the step's sub-steps have spent it, the sub-step in hand ends the step
/// like the last sub-step of (4.3b), and one body's step costs at most twice the budget (a
/// millimetre plate with friction 5 at dt = 0.1 s took 390 solves per step, most at the sweep
/// cap, with 64 searches per sub-step and 32 sub-steps).
constexpr int kMaxImpactSearches = 64;
/// The search of (4.3a) stops once the clear and the crossing sub-steps agree to this fraction.
constexpr Real kBisectionResolution = 1e-9;
/// (4.3a) aims the end height of the arriving vertex between the impact tolerance (below which
/// the time of impact calls the sub-step crossing) and the impact band (at or below which a
/// clear sub-step ends the search): half way, in impact tolerances.
constexpr Real kBracketAim = 1.5;
/// Slots per batch: the unit step() hands to a thread. Fixed, so the batches (and the order in
/// which their events are merged) do not depend on the number of threads; small enough that a
/// few thousand bodies make enough batches to balance two to sixteen threads, large enough that
/// handing one out costs little next to advancing it.
constexpr std::size_t kBatchSize = 32;
/// Impacts reserved per body, so that a step allocates nothing in the usual case: a body has at
/// most one impact in almost every step, and bodies of a batch do not all hit in the same one.
/// (A CollisionEvent carries its manifold, 1.2 kB; each reserved impact costs that twice, in the
/// batch's list and the world's.)
constexpr std::size_t kReservedImpactsPerBody = 1;

[[maybe_unused]] bool isValidDef(const BodyDef& def)
{
    return std::isfinite(def.mass) && def.mass > 0.0 && isFinite(def.shape.size) &&
           def.shape.size.x > 0.0 && def.shape.size.y > 0.0 && def.shape.size.z > 0.0 &&
           isFinite(def.position) && isFinite(def.orientation) && isFinite(def.linearVelocity) &&
           isFinite(def.angularVelocity);
}

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

/// After an impact found by the time of impact, the lowest vertex is at most kImpactBand impact
/// tolerances above the plane: put it on the plane, a translation that lowers the potential
/// energy by at most m g times that height (04-detection.md, (4.5)).
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

/// (4.3a): the sub-step's length between the longest known to be clear and the shortest known
/// to cross, each with the end height above the aim of the lowest free vertex under its own
/// re-solved motion, and the next length to try: false position on that height, with the
/// Illinois halving (an end kept twice in a row has its height halved, so the other end cannot
/// stall), or the midpoint where the heights do not straddle the aim (a vertex that dips below
/// the plane and comes back up within the crossing sub-step).
class SubstepBracket {
public:
    void markClear(Real length, Real heightAboveAim)
    {
        m_clear = length;
        m_clearHeight = heightAboveAim;
        if (m_lastMoved > 0) {
            m_crossingHeight *= 0.5;
        }
        m_lastMoved = 1;
    }

    void markCrossing(Real length, Real heightAboveAim)
    {
        m_crossing = length;
        m_crossingHeight = heightAboveAim;
        if (m_lastMoved < 0) {
            m_clearHeight *= 0.5;
        }
        m_lastMoved = -1;
    }

    [[nodiscard]] Real clear() const { return m_clear; }
    [[nodiscard]] bool hasCrossing() const { return std::isfinite(m_crossing); }
    [[nodiscard]] bool closed() const
    {
        return m_crossing - m_clear <= kBisectionResolution * m_crossing;
    }

    [[nodiscard]] Real next() const
    {
        if (m_clearHeight > 0.0 && m_crossingHeight < 0.0) {
            const Real interpolated = m_clear + (m_crossing - m_clear) * m_clearHeight /
                                                    (m_clearHeight - m_crossingHeight);
            if (interpolated > m_clear && interpolated < m_crossing) {
                return interpolated;
            }
        }
        return 0.5 * (m_clear + m_crossing);
    }

private:
    Real m_clear = 0.0;
    Real m_crossing = std::numeric_limits<Real>::infinity();
    Real m_clearHeight = 0.0;
    Real m_crossingHeight = 0.0;
    /// +1 when the clear end moved last, -1 the crossing end, 0 neither yet.
    int m_lastMoved = 0;
};

} // namespace

World::World(const WorldSettings& settings) : m_settings(settings) {}

void World::setGravity(const Vec3& gravity)
{
    for (Slot& slot : m_slots) {
        // The potential energy is measured in the gravity field: a new field changes it.
        slot.body.ledger.added += slot.body.potentialEnergy(gravity) -
                                  slot.body.potentialEnergy(m_settings.gravity);
        wake(slot.body);
    }
    m_settings.gravity = gravity;
}

void World::setGround(const std::optional<Plane>& ground)
{
    m_ground = ground;
    for (Slot& slot : m_slots) {
        wake(slot.body);
    }
}

BodyId World::createBody(const BodyDef& def)
{
    TUMBLE_ASSERT(isValidDef(def));
    std::uint32_t index = 0;
    if (!m_freeSlots.empty()) {
        index = m_freeSlots.back();
        m_freeSlots.pop_back();
    } else {
        index = static_cast<std::uint32_t>(m_slots.size());
        m_slots.emplace_back();
    }
    Slot& slot = m_slots[index];
    if (index + 1 > m_batchEvents.size() * kBatchSize) {
        m_batchEvents.emplace_back();
        m_batchEvents.back().collisions.reserve(kBatchSize * kReservedImpactsPerBody);
        m_batchEvents.back().restEvents.reserve(kBatchSize);
    }
    // Grown geometrically: reserving the exact count would reallocate on every creation.
    if (m_restEvents.capacity() < m_slots.size()) {
        const std::size_t bodies = std::max(m_slots.size(), 2 * m_restEvents.capacity());
        m_collisions.reserve(bodies * kReservedImpactsPerBody);
        m_restEvents.reserve(bodies);
    }
    slot.body = makeBody(def);
    slot.body.ledger.initial = energyOf(slot.body);
    slot.alive = true;
    slot.touchingGround = false;
    slot.warmStart = WarmStartCache{};
    return BodyId{index, slot.generation};
}

void World::destroyBody(BodyId id)
{
    TUMBLE_ASSERT(isValid(id));
    Slot& slot = m_slots[id.index];
    slot.alive = false;
    ++slot.generation;
    m_freeSlots.push_back(id.index);
}

bool World::isValid(BodyId id) const
{
    return id.index < m_slots.size() && m_slots[id.index].alive &&
           m_slots[id.index].generation == id.generation;
}

const Body& World::body(BodyId id) const
{
    TUMBLE_ASSERT(isValid(id));
    return m_slots[id.index].body;
}

Body& World::mutableBody(BodyId id)
{
    TUMBLE_ASSERT(isValid(id));
    return m_slots[id.index].body;
}

std::vector<BodyId> World::bodyIds() const
{
    std::vector<BodyId> ids;
    for (std::uint32_t index = 0; index < m_slots.size(); ++index) {
        if (m_slots[index].alive) {
            ids.push_back(BodyId{index, m_slots[index].generation});
        }
    }
    return ids;
}

void World::wake(Body& body)
{
    body.asleep = false;
    body.slowTime = 0.0;
}

template <typename Change>
void World::editBody(BodyId id, Change change)
{
    Body& body = mutableBody(id);
    const Real energyBefore = energyOf(body);
    change(body);
    body.ledger.added += energyOf(body) - energyBefore;
    wake(body);
}

void World::setMass(BodyId id, Real mass)
{
    TUMBLE_ASSERT(std::isfinite(mass) && mass > 0.0);
    editBody(id, [&](Body& body) {
        body.mass = mass;
        refreshMassProperties(body);
    });
}

void World::setSize(BodyId id, const Vec3& size)
{
    TUMBLE_ASSERT(isFinite(size) && size.x > 0.0 && size.y > 0.0 && size.z > 0.0);
    editBody(id, [&](Body& body) {
        body.shape.size = size;
        refreshMassProperties(body);
    });
}

void World::setTransform(BodyId id, const Vec3& position, const Quat& orientation)
{
    editBody(id, [&](Body& body) {
        body.position = position;
        body.orientation = glm::normalize(orientation);
        refreshWorldInertia(body);
    });
}

void World::setLinearVelocity(BodyId id, const Vec3& velocity)
{
    editBody(id, [&](Body& body) { body.linearVelocity = velocity; });
}

void World::setAngularVelocity(BodyId id, const Vec3& angularVelocity)
{
    editBody(id, [&](Body& body) { body.angularVelocity = angularVelocity; });
}

void World::setMaterial(BodyId id, const Material& material)
{
    editBody(id, [&](Body& body) { body.material = material; });
}

void World::applyImpulse(BodyId id, const Vec3& impulse, const Vec3& worldPoint)
{
    editBody(id, [&](Body& body) {
        applyImpulseAtOffset(body, impulse, worldPoint - body.position);
    });
}

ContactManifold World::contactsOf(BodyId id) const
{
    const Body& body = this->body(id);
    // Built in place (a manifold is over a kilobyte: an empty one assigned over was a zeroing
    // and a copy per sub-step).
    ContactManifold manifold =
        m_ground ? collideCuboidPlane({body.position, body.orientation}, body.shape.halfExtents(),
                                      *m_ground, m_settings.contactTolerance)
                 : ContactManifold{};
    manifold.body = id;
    return manifold;
}

int World::threadCount() const
{
    if (m_settings.threads > 0) {
        return m_settings.threads;
    }
    return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

void World::step(Real dt)
{
    TUMBLE_ASSERT(std::isfinite(dt) && dt > 0.0);
    m_collisions.clear();
    m_restEvents.clear();
    m_contactRecords.clear();
    const auto batches = static_cast<std::ptrdiff_t>(m_batchEvents.size());
    const int threads = threadCount();
    if (threads > 1 && batches > 1) {
#ifdef TUMBLE_HAVE_OPENMP
        // Batches go to threads as they finish the previous one (bodies at rest cost nothing,
        // so a static split would leave threads idle); each body is advanced alone, whichever
        // thread takes it, so the results do not depend on the schedule.
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
#endif
        for (std::ptrdiff_t batch = 0; batch < batches; ++batch) {
            advanceBatch(static_cast<std::size_t>(batch), dt);
        }
    } else {
        // One thread: no parallel region at all (even an inactive one costs a team setup).
        for (std::ptrdiff_t batch = 0; batch < batches; ++batch) {
            advanceBatch(static_cast<std::size_t>(batch), dt);
        }
    }
    for (const StepEvents& events : m_batchEvents) {
        m_collisions.insert(m_collisions.end(), events.collisions.begin(), events.collisions.end());
        m_restEvents.insert(m_restEvents.end(), events.restEvents.begin(), events.restEvents.end());
        m_contactRecords.insert(m_contactRecords.end(), events.contactRecords.begin(),
                                events.contactRecords.end());
    }
    m_time += dt;
}

void World::advanceBatch(std::size_t batch, Real dt)
{
    StepEvents& events = m_batchEvents[batch];
    events.collisions.clear();
    events.restEvents.clear();
    events.contactRecords.clear();
    const std::size_t end = std::min(m_slots.size(), (batch + 1) * kBatchSize);
    for (std::size_t index = batch * kBatchSize; index < end; ++index) {
        Slot& slot = m_slots[index];
        if (!slot.alive || slot.body.asleep) {
            continue;
        }
        slot.body.ledger.impactWorkLastStep = 0.0;
        const BodyId id{static_cast<std::uint32_t>(index), slot.generation};
        if (m_settings.response == ContactResponse::Average) {
            advanceAverage(id, slot, dt, events);
        } else {
            advanceSequential(id, slot, dt, events);
        }
        updateRest(id, slot, dt, events);
    }
}

bool World::clearOfGroundForStep(const Body& body, Real dt) const
{
    if (!m_ground) {
        return true;
    }
    // No vertex is farther than the half diagonal from the centre, whatever the rotation, and
    // the normal velocity changes linearly over the step (constant gravity), so the centre sinks
    // by at most dt times the larger of its start and end approach speeds (04-detection.md,
    // (4.7)). Twice the contact tolerance plus a rounding margin keeps every vertex outside the
    // tolerance until the end of the step.
    const Real normalStart = glm::dot(Plane::normal(), body.linearVelocity);
    const Real normalEnd = normalStart + glm::dot(Plane::normal(), m_settings.gravity) * dt;
    const Real sink = dt * std::max({0.0, -normalStart, -normalEnd});
    const Real radius = glm::length(body.shape.halfExtents());
    const Real centreHeight = glm::dot(Plane::normal(), body.position) - m_ground->height;
    const Real clearance =
        2.0 * m_settings.contactTolerance + 1e-12 * (radius + std::abs(centreHeight));
    if (centreHeight - radius - sink > clearance) {
        return true;
    }
    // (4.7a): closer in, the lowest vertex itself, lowered by the sink and by the most the
    // rotation can carry a vertex over the step, its turning rate (4.4) times the half diagonal.
    // A body bouncing or rocking a little above the plane (a 2 x 6 x 2 cuboid lying flat has
    // its centre 1 m up and a half diagonal of 3.3 m) skips the search this way.
    // (The rotation's bound costs more than the heights: a body resting on the plane, whose
    // lowest vertex is already within the clearance, does not need it.)
    const Real lowest = lowestVertexHeight({body.position, body.orientation},
                                           body.shape.halfExtents(), *m_ground);
    if (!(lowest - sink > clearance)) {
        return false;
    }
    const Real turn =
        dt * radius *
        rotationBounds(body.orientation, body.angularVelocity, body.inertiaBody(), dt,
                       m_settings.integrator)
            .total();
    return lowest - turn - sink > clearance;
}

void World::moveFreely(Body& body, Real dt) const
{
    // Gravity, then the position and rotation over dt, its energy change booked to the
    // integrator.
    const Real energyStart = energyOf(body);
    const Vec3 velocityStart = body.linearVelocity;
    body.linearVelocity += m_settings.gravity * dt;
    integratePositions(body, velocityStart, dt);
    bookContact(body, ContactWork{}, energyOf(body) - energyStart, false);
}

void World::advanceInFlight(Slot& slot, Real dt) const
{
    // The stages of advanceSequential for a body that touches nothing, with the same operations
    // in the same order, so the result is the same to the bit: gravity, then the position and
    // rotation over the step.
    moveFreely(slot.body, dt);
    // No vertex in contact: the solve reads a cache's rates only for the vertices it lists.
    slot.warmStart.vertices = 0;
    slot.touchingGround = false;
}

void World::advanceSequential(BodyId id, Slot& slot, Real dt, StepEvents& events)
{
    Body& body = slot.body;
    if (clearOfGroundForStep(body, dt)) {
        advanceInFlight(slot, dt);
        return;
    }
    const ContactSolveSettings solveSettings{m_settings.restitutionThreshold,
                                             m_settings.solverIterations};
    Real elapsed = 0.0;
    int searches = 0;
    // The body's energy now, carried from stage to stage: each booking's "after" is the next
    // one's "before" (the ledger's energies are a sizeable part of a resting step).
    Real energy = energyOf(body);
    for (int substep = 0;; ++substep) {
        const Real remaining = dt - elapsed;
        // 1. Detect the vertices touching the ground now.
        ContactManifold contacts = contactsOf(id);
        // 2. Resolve an impact at once (restitution and friction impulses) when an approaching
        //    vertex has reached the plane; approaching vertices still above it are left to the
        //    time of impact, so the impact happens at the plane.
        if (approachSpeed(body, contacts) > kImpactSpeed) {
            if (lowestApproachingHeight(body, contacts) <= kImpactBand * impactTolerance()) {
                const ImpactOutcome outcome = resolveImpact(body, contacts, solveSettings);
                const Real energyAfterImpact = energyOf(body);
                bookContact(body, outcome.work, energyAfterImpact - energy, true);
                recordImpact(contacts, outcome, m_time + elapsed, events);
                recordContacts(ContactPhase::Impact, contacts, m_time + elapsed, events);
                settleOnPlane(body, contacts);
                energy = bookCorrection(body, energyAfterImpact);
            } else {
                dropApproachingPoints(body, contacts);
            }
        }
        // 3. Integrate velocities over the sub-step: gravity, then resting contact.
        const Real energyStart = energy;
        const Vec3 velocityStart = body.linearVelocity;
        const Vec3 angularVelocityStart = body.angularVelocity;
        Real tau = remaining;
        ContactWork restingWork = integrateVelocities(body, contacts, tau, slot.warmStart);
        // 4. Shorten the sub-step to the first impact of another vertex.
        //    The resting-contact solve depends on tau, so the motion over a shortened sub-step
        //    is not the one searched: search again until no vertex crosses within it. When the
        //    motion re-solved for the shortened sub-step no longer comes near the plane, the
        //    impact belonged to the longer solve only: search between the longest sub-step
        //    known to be clear and the shortest known to cross (04-detection.md, (4.3a)).
        const std::uint8_t touching = vertexMask(contacts);
        const Vec3 halfExtents = body.shape.halfExtents();
        const Real aim = kBracketAim * impactTolerance();
        SubstepBracket bracket;
        bool tauIsClear = false;
        for (int search = 0; m_ground && search < kMaxImpactSearches; ++search) {
            ++searches;
            const SubstepMotion motion =
                substepMotion(body, positionStartVelocity(velocityStart, body, contacts), tau);
            const Real impact =
                timeOfImpact(motion, halfExtents, *m_ground, touching, impactTolerance());
            Real next = 0.0;
            if (impact >= tau) {
                // Done when nothing crossed, when the vertex found ends the sub-step at the
                // impact tolerance (a real impact, met next sub-step), or when the bracket is
                // closed. (The end height costs a pose: it is only needed with a bracket.)
                if (!bracket.hasCrossing()) {
                    tauIsClear = true;
                    break;
                }
                const Real endHeight = freeClearance(motion, halfExtents, *m_ground, touching, tau);
                bracket.markClear(tau, endHeight - aim);
                if (endHeight <= kImpactBand * impactTolerance() || bracket.closed()) {
                    tauIsClear = true;
                    break;
                }
                next = bracket.next();
            } else if (freeClearance(motion, halfExtents, *m_ground, touching, impact) >
                       impactTolerance()) {
                // The search ran out of advances before any vertex arrived (one grazes the
                // plane): the motion is only known to be clear until then. Shorten the sub-step
                // to it, or, once a longer sub-step is known to be clear, take that one: going
                // back to the bracket alternated between the two up to the search cap, and
                // every undecided search costs its full advances.
                if (bracket.clear() > 0.0) {
                    break;
                }
                next = impact;
            } else {
                bracket.markCrossing(
                    tau, freeClearance(motion, halfExtents, *m_ground, touching, tau) - aim);
                next = bracket.clear() > 0.0 ? bracket.next() : impact;
            }
            body.linearVelocity = velocityStart;
            body.angularVelocity = angularVelocityStart;
            tau = next;
            restingWork = integrateVelocities(body, contacts, tau, slot.warmStart);
        }
        if (!tauIsClear && bracket.clear() > 0.0) {
            body.linearVelocity = velocityStart;
            body.angularVelocity = angularVelocityStart;
            tau = bracket.clear();
            restingWork = integrateVelocities(body, contacts, tau, slot.warmStart);
        }
        slot.warmStart = makeWarmStart(contacts, tau);
        recordContacts(ContactPhase::Resting, contacts, m_time + elapsed, events);
        // 5. Integrate positions and orientation.
        integratePositions(body, positionStartVelocity(velocityStart, body, contacts), tau);
        const Real energyAfterMotion = energyOf(body);
        bookContact(body, restingWork, energyAfterMotion - energyStart, false);
        // 6. Keep the vertices that carried load on the plane, and push the body out of any
        //    penetration left by the sub-step.
        keepLoadBearingOnPlane(body, contacts);
        correctPenetration(body);
        energy = bookCorrection(body, energyAfterMotion);
        // (not "tau == remaining": with a NaN state that never holds and the step never ended)
        if (!(tau < remaining)) {
            break;
        }
        elapsed += tau;
        // elapsed + tau can round up to dt when tau falls short of the remaining time by less
        // than an ulp: the step is then complete, and another sub-step would have length zero.
        if (!(elapsed < dt)) {
            break;
        }
        // (4.3b): the last sub-step allowed, or one that brought the step's searches to their
        // budget, ends the step, short of dt if it must.
        if (substep + 1 >= kMaxSubsteps || searches >= kMaxImpactSearches) {
            break;
        }
    }
    // The predicate of detection (4.1) without building the manifold: some vertex within the
    // contact tolerance.
    slot.touchingGround =
        m_ground && lowestVertexHeight({body.position, body.orientation},
                                       body.shape.halfExtents(),
                                       *m_ground) <= m_settings.contactTolerance;
}

void World::advanceAverage(BodyId id, Slot& slot, Real dt, StepEvents& events)
{
    Body& body = slot.body;
    // The handouts' order: move freely for the whole step, then detect and respond.
    moveFreely(body, dt);
    ContactManifold contacts = contactsOf(id);
    const bool wasTouching = slot.touchingGround;
    slot.touchingGround = contacts.pointCount > 0;
    if (contacts.pointCount == 0) {
        return;
    }
    // Move the body up so its lowest vertex lies on the plane (handout part 2, task 3).
    const Real lift = contacts.maxPenetration();
    const Real energyBeforeLift = energyOf(body);
    body.position += lift * contacts.normal;
    // A fast body can end the free step far below the plane (755 m/s at dt = 0.1 s: 75 m), and
    // the lift then leaves the lowest vertex below it by the rounding of that depth (5e-15 m, the
    // world-stepping fuzzer): the push-out (4.5) takes the remainder.
    correctPenetration(body);
    bookCorrection(body, energyBeforeLift);
    for (int i = 0; i < contacts.pointCount; ++i) {
        contacts.points[i].position += lift * contacts.normal;
    }
    const ContactSolveSettings solveSettings{m_settings.restitutionThreshold,
                                             m_settings.solverIterations};
    const Real energyBeforeImpulse = energyOf(body);
    const ImpactOutcome outcome = resolveAverageContact(body, contacts, solveSettings);
    bookContact(body, outcome.work, energyOf(body) - energyBeforeImpulse, true);
    recordContacts(ContactPhase::Average, contacts, m_time + dt, events);
    // A resting body gains |g| dt of approach every step; only a real impact is reported.
    const Real restingApproach = glm::length(m_settings.gravity) * dt;
    if (outcome.approachSpeed > 0.0 &&
        (!wasTouching ||
         outcome.approachSpeed > m_settings.restitutionThreshold + restingApproach)) {
        recordImpact(contacts, outcome, m_time + dt, events);
    }
}

Real World::impactTolerance() const
{
    return kImpactTolerance * m_settings.contactTolerance;
}

ContactWork World::integrateVelocities(Body& body, ContactManifold& contacts, Real tau,
                                       const WarmStartCache& warmStart) const
{
    return solveRestingContact(body, contacts, m_settings.gravity * tau, tau,
                               {m_settings.restitutionThreshold, m_settings.solverIterations},
                               warmStart);
}

void World::bookContact(Body& body, const ContactWork& work, Real energyChange, bool impact) const
{
    // (8.3): the contact impulses' work is booked to them; whatever else changed the energy in
    // the same stage (gravity over a sub-step, the rotation split, rounding) is the integrator's.
    const Real contactWork = work.normal + work.friction;
    body.ledger.removedByNormal -= work.normal;
    body.ledger.removedByFriction -= work.friction;
    body.ledger.removedByIntegration -= energyChange - contactWork;
    if (impact) {
        body.ledger.impactWorkLastStep += contactWork;
    }
}

Real World::bookCorrection(Body& body, Real energyBefore) const
{
    const Real energyAfter = energyOf(body);
    body.ledger.removedByCorrection += energyBefore - energyAfter;
    return energyAfter;
}

void World::recordContacts(ContactPhase phase, const ContactManifold& contacts, Real time,
                           StepEvents& events) const
{
    if (m_settings.recordContacts && contacts.pointCount > 0) {
        events.contactRecords.push_back(
            ContactRecord{time, phase, body(contacts.body).position, contacts});
    }
}

Vec3 World::positionStartVelocity(const Vec3& velocityStart, const Body& body,
                                  const ContactManifold& contacts)
{
    // (2.2a): in free flight the mean of the start and end velocities moves the centre exactly.
    // When the ground pushed, the normal part of the end velocity is what it allowed; the mean
    // would move the body by half of what they removed (a rebound stopped by resting contact
    // would still lift the body, putting potential energy in with no velocity to match), so the
    // normal component moves with the end velocity, semi-implicitly. Tangential motion keeps the
    // mean, which makes sliding under friction exact.
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

SubstepMotion World::substepMotion(const Body& body, const Vec3& velocityStart, Real tau) const
{
    SubstepMotion motion;
    motion.start = {body.position, body.orientation};
    // Semi-implicit Euler for the handout integrator: the end velocity for the whole sub-step.
    motion.velocityStart =
        m_settings.integrator == Integrator::Exact ? velocityStart : body.linearVelocity;
    motion.velocityEnd = body.linearVelocity;
    motion.angularVelocity = body.angularVelocity;
    motion.inertiaBody = body.inertiaBody();
    motion.tau = tau;
    motion.integrator = m_settings.integrator;
    return motion;
}

void World::integratePositions(Body& body, const Vec3& velocityStart, Real tau) const
{
    // (2.2): with the velocity changing uniformly over the sub-step the mean velocity is exact;
    // the handout integrator takes the end velocity (semi-implicit Euler, (2.3)).
    const Vec3 mean = m_settings.integrator == Integrator::Exact
                          ? 0.5 * (velocityStart + body.linearVelocity)
                          : body.linearVelocity;
    body.position += tau * mean;
    integrateRotation(body, tau, m_settings.integrator);
}

void World::keepLoadBearingOnPlane(Body& body, const ContactManifold& contacts) const
{
    // (4.6): a vertex that pushed on the ground this sub-step ends it with zero normal velocity,
    // but the position update is exact only to second order, so a body turning about such a
    // vertex drifts off the plane by about tau^2 |w|^2 |r|. Bring the lowest of them back down;
    // like (4.5) this moves the body without touching its velocity.
    if (!m_ground) {
        return;
    }
    const std::array<Real, 8> heights =
        vertexHeights({body.position, body.orientation}, body.shape.halfExtents(), *m_ground);
    Real lowest = std::numeric_limits<Real>::infinity();
    for (int i = 0; i < contacts.pointCount; ++i) {
        if (contacts.points[i].normalImpulse > 0.0) {
            lowest = std::min(lowest, heights[contacts.points[i].vertex]);
        }
    }
    if (lowest > 0.0 && lowest <= m_settings.contactTolerance) {
        body.position -= lowest * Plane::normal();
    }
}

void World::correctPenetration(Body& body) const
{
    if (!m_ground) {
        return;
    }
    // (4.5): a pure translation along the normal; velocities are untouched, so no kinetic
    // energy is added.
    const Real lowest =
        lowestVertexHeight({body.position, body.orientation}, body.shape.halfExtents(), *m_ground);
    if (lowest < 0.0) {
        body.position -= lowest * Plane::normal();
    }
}

void World::recordImpact(const ContactManifold& contacts, const ImpactOutcome& outcome, Real time,
                         StepEvents& events)
{
    CollisionEvent event;
    event.time = time;
    event.manifold = contacts;
    event.approachSpeed = outcome.approachSpeed;
    event.normalImpulse = outcome.normalImpulse;
    event.frictionImpulse = outcome.frictionImpulse;
    event.restitutionApplied = outcome.restitutionApplied;
    event.kineticEnergyBefore = outcome.kineticEnergyBefore;
    event.kineticEnergyAfter = outcome.kineticEnergyAfter;
    events.collisions.push_back(event);
}

void World::updateRest(BodyId id, Slot& slot, Real dt, StepEvents& events) const
{
    Body& body = slot.body;
    const bool slow = slot.touchingGround &&
                      glm::length(body.linearVelocity) < m_settings.sleepLinearSpeed &&
                      glm::length(body.angularVelocity) < m_settings.sleepAngularSpeed;
    const Real slowBefore = body.slowTime;
    if (slow && slowBefore == 0.0) {
        slot.slowSince = m_time + dt;
    }
    body.slowTime = slow ? body.slowTime + dt : 0.0;
    if (slowBefore >= m_settings.sleepTime || body.slowTime < m_settings.sleepTime) {
        return;
    }
    // The body has just stayed slow for sleepTime: it is at rest since it became slow.
    events.restEvents.push_back(
        RestEvent{id, slot.slowSince, faceAlong(body.orientation, -Plane::normal())});
    if (m_settings.allowSleep) {
        body.ledger.removedByRest += body.kineticEnergy();
        body.asleep = true;
        body.linearVelocity = Vec3(0.0);
        body.angularVelocity = Vec3(0.0);
    }
}

} // namespace tumble
