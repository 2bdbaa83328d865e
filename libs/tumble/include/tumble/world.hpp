// World: owns the bodies, gravity and the ground, and steps them with a fixed dt.
#pragma once

#include "tumble/body.hpp"
#include "tumble/body_id.hpp"
#include "tumble/contact.hpp"
#include "tumble/events.hpp"
#include "tumble/math.hpp"
#include "tumble/settings.hpp"
#include "tumble/shape.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace tumble {

struct BodySlot;
struct CoupledIsland;
struct StepContext;
struct StepEvents;

namespace detail {
struct StepScratch;
/// The step's working buffers (broad phase, islands, their events); a copied World starts with
/// empty ones.
class StepScratchHandle {
public:
    StepScratchHandle();
    StepScratchHandle(const StepScratchHandle& other);
    StepScratchHandle(StepScratchHandle&& other) noexcept;
    StepScratchHandle& operator=(const StepScratchHandle& other);
    StepScratchHandle& operator=(StepScratchHandle&& other) noexcept;
    ~StepScratchHandle();
    [[nodiscard]] StepScratch& get() const { return *m_scratch; }

private:
    std::unique_ptr<StepScratch> m_scratch;
};
} // namespace detail

/// Owns every body, the gravity and the ground; advances them with step(dt).
class World {
public:
    explicit World(const WorldSettings& settings = {});
    World(const World& other);
    World(World&& other) noexcept;
    World& operator=(const World& other);
    World& operator=(World&& other) noexcept;
    ~World();

    [[nodiscard]] const WorldSettings& settings() const { return m_settings; }
    void setGravity(const Vec3& gravity);
    void setIntegrator(Integrator integrator) { m_settings.integrator = integrator; }
    void setResponse(ContactResponse response) { m_settings.response = response; }
    /// See WorldSettings::threads (0: one per core).
    void setThreads(int threads) { m_settings.threads = threads; }
    /// The number of threads step() uses: WorldSettings::threads, or the cores when it is 0.
    [[nodiscard]] int threadCount() const;

    /// The ground plane, or none.
    [[nodiscard]] const std::optional<Plane>& ground() const { return m_ground; }
    void setGround(const std::optional<Plane>& ground);

    /// The ground's own material, or none: its contacts take the dynamic body's (the handouts').
    [[nodiscard]] const std::optional<Material>& groundMaterial() const { return m_groundMaterial; }
    void setGroundMaterial(const std::optional<Material>& material);

    /// Adds a static half-space (its normal must be a unit vector) and returns its index.
    int addPlane(const StaticPlane& plane);
    /// The half-spaces besides the ground, in the order they were added.
    [[nodiscard]] std::span<const StaticPlane> planes() const { return m_planes; }

    /// Adds a body; its mass and size must be positive and finite (checked by TUMBLE_ASSERT).
    BodyId createBody(const BodyDef& def);
    void destroyBody(BodyId id);
    /// True while `id` names a live body (false after destroyBody, or for a default id).
    [[nodiscard]] bool isValid(BodyId id) const;
    [[nodiscard]] const Body& body(BodyId id) const;
    /// Ids of the live bodies, in creation order.
    [[nodiscard]] std::vector<BodyId> bodyIds() const;

    /// Changes the mass and recomputes the body-frame and world-frame inverse inertia.
    void setMass(BodyId id, Real mass);
    /// Changes the full size (width, height, depth) and recomputes the inverse inertia.
    void setSize(BodyId id, const Vec3& size);
    void setTransform(BodyId id, const Vec3& position, const Quat& orientation);
    void setLinearVelocity(BodyId id, const Vec3& velocity);
    void setAngularVelocity(BodyId id, const Vec3& angularVelocity);
    void setMaterial(BodyId id, const Material& material);
    /// Applies `impulse` (N s) at `worldPoint`: dv = J/m, dw = I^-1 (r x J) with r the offset
    /// from the centre of mass (docs/physics/03-impulses.md). Wakes the body.
    void applyImpulse(BodyId id, const Vec3& impulse, const Vec3& worldPoint);

    /// Advances every awake body by dt seconds (dt > 0). Bodies alone with the ground allocate
    /// nothing once the event buffers hold a step's events (they are reserved as bodies are
    /// created; recording contacts and more than two impacts of each body in one step may grow
    /// them); islands of touching bodies still allocate their working buffers every step.
    void step(Real dt);
    /// Simulated time, s: the sum of the dt of every step.
    [[nodiscard]] Real time() const { return m_time; }

    /// Impacts during the last step, in order.
    [[nodiscard]] std::span<const CollisionEvent> collisions() const { return m_collisions; }
    /// Bodies that came to rest during the last step.
    [[nodiscard]] std::span<const RestEvent> restEvents() const { return m_restEvents; }
    /// Every contact solve of the last step, when WorldSettings::recordContacts is set.
    [[nodiscard]] std::span<const ContactRecord> contactRecords() const { return m_contactRecords; }
    /// What the island solver did in the last step.
    [[nodiscard]] const SolverStatistics& solverStatistics() const { return m_solverStatistics; }
    /// Kinetic plus potential energy of a body, J.
    [[nodiscard]] Real energyOf(const Body& body) const
    {
        return body.kineticEnergy() + body.potentialEnergy(m_settings.gravity);
    }
    /// Touching vertices of a body at its current pose (empty manifold without a ground).
    [[nodiscard]] ContactManifold contactsOf(BodyId id) const;

private:
    Body& mutableBody(BodyId id);
    /// Runs `change` on a body and books the energy it adds as added by the user.
    template <typename Change>
    void editBody(BodyId id, Change change);
    [[nodiscard]] StepContext stepContext() const;
    void findPairs(detail::StepScratch& scratch, Real dt);
    /// The touch test (10.4) of each of the broad phase's pairs.
    void testBroadPairs(detail::StepScratch& scratch, Real dt);
    /// (12.5b): answers the broad phase's pair k from its kept island, if it has one.
    bool answerFromKeptIsland(detail::StepScratch& scratch, std::size_t k) const;
    /// The touch test (10.4) of the broad phase's pair k, not of a kept island, answered for a
    /// resting pair (10.4b).
    void testBroadPair(detail::StepScratch& scratch, std::size_t k, Real dt);
    /// (12.5b): marks the bodies of the kept soft islands that stayed put (keptLeader).
    void markKeptSoftIslands(detail::StepScratch& scratch) const;
    /// (12.5b): the touch test's answer for a pair within one of them (or between one of
    /// their bodies and a static body), as its island's pairs give it; none for another pair.
    [[nodiscard]] std::optional<bool> keptSoftTouch(const detail::StepScratch& scratch,
                                                    std::uint32_t lower,
                                                    std::uint32_t upper) const;
    /// The points of the broad phase's pair `broadPair` (lower, upper) over the step, for a
    /// pair whose test found none: a resting one (10.4b) or one answered by keptSoftTouch.
    void findPairPoints(detail::StepScratch& scratch, std::uint32_t broadPair,
                        std::uint32_t lower, std::uint32_t upper, Real dt);
    /// Finds the points of an island's pairs answered by keptSoftTouch when the island is not
    /// the one kept (a body joined it): its step builds its manifolds from them.
    void findKeptPairPoints(detail::StepScratch& scratch, std::span<const std::uint32_t> links,
                            CoupledIsland& island, Real dt);
    void buildStepIslands(detail::StepScratch& scratch, Real dt);
    /// (12.5b): which soft islands step on the manifolds they kept; the impulses of every
    /// other kept island go to its bodies' caches first.
    void decideKeptSoftIslands(detail::StepScratch& scratch);
    /// The island's pairs from its links, and in a soft world their points.
    void addIslandPairs(detail::StepScratch& scratch, std::span<const std::uint32_t> links,
                        CoupledIsland& island, Real dt);
    void advanceSolitaryBodies(Real dt);
    void advanceBatch(std::size_t batch, Real dt);
    void advanceCoupledIslands(detail::StepScratch& scratch, Real dt);
    void mergeEvents(const detail::StepScratch& scratch);

    WorldSettings m_settings;
    std::optional<Plane> m_ground;
    std::optional<Material> m_groundMaterial;
    std::vector<StaticPlane> m_planes;
    std::vector<BodySlot> m_slots;
    std::vector<std::uint32_t> m_freeSlots;
    Real m_time = 0.0;
    /// Edits of bodies and static geometry so far: a step keeps nothing built before one.
    std::uint64_t m_edits = 0;
    std::vector<CollisionEvent> m_collisions;
    std::vector<RestEvent> m_restEvents;
    std::vector<ContactRecord> m_contactRecords;
    SolverStatistics m_solverStatistics;
    /// One per batch of kBatchSize slots.
    std::vector<StepEvents> m_batchEvents;
    detail::StepScratchHandle m_scratch;
};

} // namespace tumble
