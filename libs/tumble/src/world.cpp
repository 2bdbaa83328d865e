// World: body storage behind ids, the setters that keep bodies consistent, and the step as the
// list of its stages.
#include "tumble/world.hpp"

#include "body_slot.hpp"
#include "body_state.hpp"
#include "dynamics/energy_booking.hpp"
#include "dynamics/rest.hpp"
#include "step/ground_stages.hpp"
#include "step/handout_step.hpp"
#include "collision/aabb.hpp"
#include "dynamics/islands.hpp"
#include "step/coupled_step.hpp"
#include "step/solitary_step.hpp"
#include "step/step_events.hpp"
#include "step/step_scratch.hpp"
#include "tumble_assert.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#ifdef TUMBLE_HAVE_OPENMP
#include <omp.h>
#endif

namespace tumble {

namespace {

/// Slots per batch: the unit step() hands to a thread. Fixed, so the batches (and the order in
/// which their events are merged) do not depend on the number of threads; small enough that a
/// few thousand bodies make enough batches to balance two to sixteen threads, large enough that
/// handing one out costs little next to advancing it.
constexpr std::size_t kBatchSize = 32;
/// Impacts reserved per body, so that a step allocates nothing in the usual case: a body has at
/// most one impact in almost every step. (A CollisionEvent carries its manifold, 1.2 kB; each
/// reserved impact costs that twice, in the batch's list and the world's.)
constexpr std::size_t kReservedImpactsPerBody = 1;

[[maybe_unused]] bool isValidDef(const BodyDef& def)
{
    return std::isfinite(def.mass) && def.mass > 0.0 && isFinite(def.shape.size) &&
           def.shape.size.x > 0.0 && def.shape.size.y > 0.0 && def.shape.size.z > 0.0 &&
           isFinite(def.position) && isFinite(def.orientation) && isFinite(def.linearVelocity) &&
           isFinite(def.angularVelocity);
}

/// The cores of the machine, read once: the C library reads them from the system on every call.
int coreCount()
{
    static const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    return cores;
}

void wake(Body& body)
{
    body.asleep = false;
    body.slowTime = 0.0;
}

} // namespace

namespace detail {
StepScratchHandle::StepScratchHandle() : m_scratch(std::make_unique<StepScratch>()) {}
StepScratchHandle::StepScratchHandle(const StepScratchHandle&) : StepScratchHandle() {}
StepScratchHandle::StepScratchHandle(StepScratchHandle&& other) noexcept = default;
StepScratchHandle& StepScratchHandle::operator=(const StepScratchHandle&) { return *this; }
StepScratchHandle& StepScratchHandle::operator=(StepScratchHandle&& other) noexcept = default;
StepScratchHandle::~StepScratchHandle() = default;
} // namespace detail

World::World(const WorldSettings& settings) : m_settings(settings) {}
World::World(const World& other) = default;
World::World(World&& other) noexcept = default;
World& World::operator=(const World& other) = default;
World& World::operator=(World&& other) noexcept = default;
World::~World() = default;

void World::setGravity(const Vec3& gravity)
{
    ++m_edits;
    for (BodySlot& slot : m_slots) {
        // The potential energy is measured in the gravity field: a new field changes it.
        slot.body.ledger.added += slot.body.potentialEnergy(gravity) -
                                  slot.body.potentialEnergy(m_settings.gravity);
        wake(slot.body);
    }
    m_settings.gravity = gravity;
}

void World::setGround(const std::optional<Plane>& ground)
{
    ++m_edits;
    m_ground = ground;
    for (BodySlot& slot : m_slots) {
        wake(slot.body);
    }
}

void World::setGroundMaterial(const std::optional<Material>& material)
{
    ++m_edits;
    m_groundMaterial = material;
    for (BodySlot& slot : m_slots) {
        wake(slot.body);
    }
}

int World::addPlane(const StaticPlane& plane)
{
    TUMBLE_ASSERT(isFinite(plane.point) && std::abs(glm::length(plane.normal) - 1.0) < 1e-9);
    ++m_edits;
    m_planes.push_back(plane);
    for (BodySlot& slot : m_slots) {
        wake(slot.body);
    }
    return static_cast<int>(m_planes.size()) - 1;
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
    ++m_edits;
    BodySlot& slot = m_slots[index];
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
    slot.body.ledger.initial = tumble::energyOf(slot.body, m_settings.gravity);
    slot.alive = true;
    slot.touchingGround = false;
    slot.warmStart = WarmStartCache{};
    slot.softContacts.clear();
    return BodyId{index, slot.generation};
}

void World::destroyBody(BodyId id)
{
    TUMBLE_ASSERT(isValid(id));
    BodySlot& slot = m_slots[id.index];
    slot.alive = false;
    slot.kept.release();
    // the island it led hands its impulses to its other bodies' caches before it goes
    storeKeptSoftIsland(slot.softKept, m_slots, threadCount());
    slot.softKept.release();
    ++m_edits;
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

template <typename Change>
void World::editBody(BodyId id, Change change)
{
    ++m_edits;
    Body& body = mutableBody(id);
    const Real energyBefore = tumble::energyOf(body, m_settings.gravity);
    change(body);
    body.ledger.added += tumble::energyOf(body, m_settings.gravity) - energyBefore;
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
    return groundContacts(id, body(id), StepContext{m_settings, m_ground, m_time});
}

int World::threadCount() const
{
    return m_settings.threads > 0 ? m_settings.threads : coreCount();
}

StepContext World::stepContext() const
{
    return StepContext{m_settings,       m_ground,      m_time, m_planes,
                       m_groundMaterial, threadCount(), m_edits};
}

void World::step(Real dt)
{
    TUMBLE_ASSERT(std::isfinite(dt) && dt > 0.0);
    detail::StepScratch& scratch = m_scratch.get();
    // broad phase: pairs of bodies whose boxes, swept over the step, overlap
    findPairs(scratch, dt);
    // islands: awake dynamic bodies joined by those pairs; static bodies join none (10.4)
    buildStepIslands(scratch, dt);
    // a soft island whose bodies stayed put keeps its manifolds (step/soft_kept_island.cpp)
    decideKeptSoftIslands(scratch);
    // a body whose only obstacle is the ground keeps the exact path (step/solitary_step.cpp)
    advanceSolitaryBodies(dt);
    // bodies that may touch each other or other static geometry (step/coupled_step.cpp)
    advanceCoupledIslands(scratch, dt);
    // events in body order, then island order, whatever the thread count
    mergeEvents(scratch);
    m_time += dt;
}

void World::advanceSolitaryBodies(Real dt)
{
    const auto batches = static_cast<std::ptrdiff_t>(m_batchEvents.size());
    // bodies alone in batches of fixed size, each advanced alone whichever thread takes it
    if (batches > 1 && threadCount() > 1) {
        [[maybe_unused]] const int threads = threadCount();
#ifdef TUMBLE_HAVE_OPENMP
        // batches go to threads as they finish the previous one: bodies at rest cost nothing,
        // so a static split would leave threads idle
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
#endif
        for (std::ptrdiff_t batch = 0; batch < batches; ++batch) {
            advanceBatch(static_cast<std::size_t>(batch), dt);
        }
    } else {
        // one thread: no parallel region at all (even an inactive one costs a team setup)
        for (std::ptrdiff_t batch = 0; batch < batches; ++batch) {
            advanceBatch(static_cast<std::size_t>(batch), dt);
        }
    }
}

void World::advanceBatch(std::size_t batch, Real dt)
{
    StepEvents& events = m_batchEvents[batch];
    events.clear();
    const StepContext context = stepContext();
    const std::size_t end = std::min(m_slots.size(), (batch + 1) * kBatchSize);
    for (std::size_t index = batch * kBatchSize; index < end; ++index) {
        BodySlot& slot = m_slots[index];
        if (!slot.alive || slot.body.asleep || slot.body.isStatic() || slot.coupled) {
            continue;
        }
        slot.contactCache.clear();
        slot.softContacts.clear();
        slot.kept.release();
        slot.softKept.release();
        slot.body.ledger.impactWorkLastStep = 0.0;
        const BodyId id{static_cast<std::uint32_t>(index), slot.generation};
        if (m_settings.response == ContactResponse::Average) {
            advanceHandoutStep(id, slot, context, dt, events);
        } else {
            advanceSolitary(id, slot, context, dt, events);
        }
        updateRest(id, slot, context, dt, events);
    }
}

void World::mergeEvents(const detail::StepScratch& scratch)
{
    m_collisions.clear();
    m_restEvents.clear();
    m_contactRecords.clear();
    m_solverStatistics = {};
    const auto append = [&](const StepEvents& events) {
        m_solverStatistics += events.statistics;
        m_collisions.insert(m_collisions.end(), events.collisions.begin(), events.collisions.end());
        m_restEvents.insert(m_restEvents.end(), events.restEvents.begin(), events.restEvents.end());
        m_contactRecords.insert(m_contactRecords.end(), events.contactRecords.begin(),
                                events.contactRecords.end());
    };
    for (const StepEvents& events : m_batchEvents) {
        append(events);
    }
    for (std::size_t k = 0; k < scratch.islands.size(); ++k) {
        append(scratch.islandEvents[k]);
    }
}

} // namespace tumble
