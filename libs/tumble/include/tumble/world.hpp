// WorldSettings and World: owns the bodies, gravity and the ground, and steps them with a fixed dt.
#pragma once

#include "tumble/body.hpp"
#include "tumble/body_id.hpp"
#include "tumble/contact.hpp"
#include "tumble/math.hpp"
#include "tumble/shape.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace tumble {

struct SubstepMotion;
struct ImpactOutcome;
struct ContactWork;

/// How orientation and angular velocity advance in free flight.
enum class Integrator : std::uint8_t {
    /// Angular momentum is conserved exactly; the rotation is a symmetric splitting into exact
    /// rotations about the momentum and two body axes (docs/physics/02-integration.md). Translation under gravity
    /// is exact. The default.
    Exact,
    /// The handouts' update: R += dt [w]x R (re-orthonormalised), w held constant in flight.
    Handout,
};

/// How contact with the ground is resolved.
enum class ContactResponse : std::uint8_t {
    /// Impulses per touching vertex with accumulated clamping, a friction cone, restitution
    /// suppressed below a threshold, time of impact within the step, resting contact and rest
    /// detection (docs/physics/04..07). The default.
    Sequential,
    /// The handouts' model: after the step, move the body up so its lowest vertex lies on the
    /// plane and apply one impulse (with friction) at the average touching vertex.
    Average,
};

/// World-level tunables. Every default is the one a scenario file gets when it omits the key.
struct WorldSettings {
    /// Gravitational acceleration, m/s^2. Default (0, -9.81, 0).
    Vec3 gravity{0.0, -9.81, 0.0};
    /// Default Integrator::Exact.
    Integrator integrator = Integrator::Exact;
    /// Default ContactResponse::Sequential.
    ContactResponse response = ContactResponse::Sequential;
    /// A vertex closer to the plane than this counts as touching it, m. Default 1e-4.
    Real contactTolerance = 1e-4;
    /// Approach speeds below this get no restitution (a plastic impact), so a body can come to
    /// rest instead of bouncing forever, m/s. Default 0.05.
    Real restitutionThreshold = 0.05;
    /// Most Gauss-Seidel sweeps per contact solve; a solve stops earlier once it has converged.
    /// Default 256 (a solve on the verge of sliding converges slowly; see docs/validation.md).
    int solverIterations = 256;
    /// A body slower than these in contact with the ground for sleepTime is at rest. Defaults
    /// 1e-3 m/s, 1e-3 rad/s and 0.5 s.
    Real sleepLinearSpeed = 1e-3;
    Real sleepAngularSpeed = 1e-3;
    Real sleepTime = 0.5;
    /// Whether a body at rest is put to sleep (velocities zeroed, not integrated until woken by
    /// an impulse or a change). Default true.
    bool allowSleep = true;
    /// Whether step() keeps a ContactRecord of every contact solve (the contact ledger).
    /// Default false.
    bool recordContacts = false;
    /// Threads step() spreads the bodies over (1: the calling thread only; 0: one per core).
    /// Bodies touch only the ground, never each other, so each is advanced on its own and the
    /// results are identical whatever the number (docs/architecture.md, "Many bodies").
    /// Default 1.
    int threads = 1;
};

/// A body that has just come to rest.
struct RestEvent {
    BodyId body{};
    /// End of the first step after which the body was slow and stayed so, s.
    Real time = 0.0;
    /// The face lying on the ground.
    CuboidFace faceDown = CuboidFace::MinusY;
};

/// Owns every body, the gravity and the ground; advances them with step(dt).
class World {
public:
    explicit World(const WorldSettings& settings = {});

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

    /// Advances every awake body by dt seconds (dt > 0). Allocates nothing once the event
    /// buffers hold a step's events (they are reserved as bodies are created; recording contacts
    /// and more than two impacts of each body in one step may grow them).
    void step(Real dt);
    /// Simulated time, s: the sum of the dt of every step.
    [[nodiscard]] Real time() const { return m_time; }

    /// Impacts during the last step, in order.
    [[nodiscard]] std::span<const CollisionEvent> collisions() const { return m_collisions; }
    /// Bodies that came to rest during the last step.
    [[nodiscard]] std::span<const RestEvent> restEvents() const { return m_restEvents; }
    /// Every contact solve of the last step, when WorldSettings::recordContacts is set.
    [[nodiscard]] std::span<const ContactRecord> contactRecords() const { return m_contactRecords; }
    /// Kinetic plus potential energy of a body, J.
    [[nodiscard]] Real energyOf(const Body& body) const
    {
        return body.kineticEnergy() + body.potentialEnergy(m_settings.gravity);
    }
    /// Touching vertices of a body at its current pose (empty manifold without a ground).
    [[nodiscard]] ContactManifold contactsOf(BodyId id) const;

private:
    struct Slot {
        Body body;
        std::uint32_t generation = 0;
        bool alive = false;
        /// Whether any vertex touched the ground at the end of the last step.
        bool touchingGround = false;
        /// End of the first step of the current slow spell, s.
        Real slowSince = 0.0;
        /// Last step's resting-contact impulses, to warm-start the next.
        WarmStartCache warmStart{};
    };

    /// What the bodies of one batch report during a step, merged into the world's lists in
    /// batch order afterwards, so the order never depends on which thread ran which batch.
    struct StepEvents {
        std::vector<CollisionEvent> collisions;
        std::vector<RestEvent> restEvents;
        std::vector<ContactRecord> contactRecords;
    };

    Body& mutableBody(BodyId id);
    static void wake(Body& body);
    void advanceBatch(std::size_t batch, Real dt);
    /// True when no vertex can come within the contact tolerance of the ground during a step
    /// of dt, whatever the body's rotation (or when there is no ground).
    [[nodiscard]] bool clearOfGroundForStep(const Body& body, Real dt) const;
    /// Gravity and integration over dt with nothing touching, booked to the energy ledger.
    void moveFreely(Body& body, Real dt) const;
    /// The sequential step of a body clear of the ground: gravity and integration only.
    void advanceInFlight(Slot& slot, Real dt) const;
    void advanceSequential(BodyId id, Slot& slot, Real dt, StepEvents& events);
    void advanceAverage(BodyId id, Slot& slot, Real dt, StepEvents& events);
    [[nodiscard]] Real impactTolerance() const;
    [[nodiscard]] ContactWork integrateVelocities(Body& body, ContactManifold& contacts, Real tau,
                                                  const WarmStartCache& warmStart) const;
    void bookContact(Body& body, const ContactWork& work, Real energyChange, bool impact) const;
    /// Books the energy a position correction changed since `energyBefore` and returns the
    /// body's energy after it.
    Real bookCorrection(Body& body, Real energyBefore) const;
    void recordContacts(ContactPhase phase, const ContactManifold& contacts, Real time,
                        StepEvents& events) const;
    /// The start velocity the position update uses (docs/physics/02-integration.md, (2.2a)).
    [[nodiscard]] static Vec3 positionStartVelocity(const Vec3& velocityStart, const Body& body,
                                                    const ContactManifold& contacts);
    [[nodiscard]] SubstepMotion substepMotion(const Body& body, const Vec3& velocityStart,
                                              Real tau) const;
    void integratePositions(Body& body, const Vec3& velocityStart, Real tau) const;
    void keepLoadBearingOnPlane(Body& body, const ContactManifold& contacts) const;
    void correctPenetration(Body& body) const;
    /// Runs `change` on a body and books the energy it adds as added by the user.
    template <typename Change>
    void editBody(BodyId id, Change change);
    static void recordImpact(const ContactManifold& contacts, const ImpactOutcome& outcome,
                             Real time, StepEvents& events);
    void updateRest(BodyId id, Slot& slot, Real dt, StepEvents& events) const;

    WorldSettings m_settings;
    std::optional<Plane> m_ground;
    std::vector<Slot> m_slots;
    std::vector<std::uint32_t> m_freeSlots;
    Real m_time = 0.0;
    std::vector<CollisionEvent> m_collisions;
    std::vector<RestEvent> m_restEvents;
    std::vector<ContactRecord> m_contactRecords;
    /// One per batch of kBatchSize slots.
    std::vector<StepEvents> m_batchEvents;
};

} // namespace tumble
