// Contacts of a cuboid with the ground plane, as detection reports them and as users see them.
#pragma once

#include "tumble/body_id.hpp"
#include "tumble/math.hpp"

#include <array>
#include <cstdint>

namespace tumble {

/// What touches the ground, named by the number of touching vertices as in the handouts:
/// 1 vertex, 2 an edge, 4 a face (3 vertices within the tolerance also mean a face).
enum class ContactFeature : std::uint8_t { None = 0, Vertex = 1, Edge = 2, Face = 4 };

/// "none", "vertex", "edge" or "face".
const char* featureName(ContactFeature feature);

/// What restitution did at a contact point.
enum class RestitutionState : std::uint8_t {
    /// The point was not approaching, or was in resting contact (restitution 0 by design).
    None,
    /// The point approached faster than the threshold: Newton's target -e vn was used.
    Applied,
    /// The point approached, but slower than the threshold: a plastic impact.
    Suppressed,
};

/// "none", "applied" or "suppressed".
const char* restitutionStateName(RestitutionState state);

/// One cuboid vertex touching or below the ground.
struct ContactPoint {
    /// Index of the vertex (see cuboidVertices), or -1 for a point of a contact between two
    /// bodies (made by a pair of features, not one vertex).
    int vertex = 0;
    /// World coordinates of the vertex, m.
    Vec3 position{0.0};
    /// How far the vertex is below the plane, m (negative: above it, within the tolerance).
    Real penetration = 0.0;
    /// Impulse along the normal the solver applied at this point in the reported event, N s.
    Real normalImpulse = 0.0;
    /// Tangential (friction) impulse applied at this point in the reported event, N s.
    Vec3 frictionImpulse{0.0};
    /// Velocity of the body's material point at the vertex before and after the solve, m/s.
    Vec3 velocityBefore{0.0};
    Vec3 velocityAfter{0.0};
    /// True when the friction impulse is on the edge of the Coulomb cone and the point still
    /// slides after the solve; false when it sticks (or carries no load).
    bool sliding = false;
    RestitutionState restitution = RestitutionState::None;
};

/// The vertices of one cuboid that touch the ground (within a tolerance).
struct ContactManifold {
    BodyId body{};
    /// The other body of a contact between two bodies; null for the ground or a plane.
    BodyId other{};
    /// Index of the plane (World::planes) when the other side is a plane; -1 otherwise.
    int plane = -1;
    /// Ground normal, pointing into the body's side of the plane.
    Vec3 normal{0.0, 1.0, 0.0};
    std::array<ContactPoint, 8> points{};
    int pointCount = 0;

    /// Vertex, edge or face, from the number of touching vertices.
    [[nodiscard]] ContactFeature feature() const;
    /// Mean of the touching vertices' world coordinates (origin when there are none).
    [[nodiscard]] Vec3 averagePoint() const;
    /// Largest penetration of any touching vertex, m (0 when there are none).
    [[nodiscard]] Real maxPenetration() const;
};

/// The resting-contact impulses of a body's last step, per vertex and per second, so the next
/// solve starts from them (warm starting, docs/physics/05-normal-impulse.md, (5.10)).
struct WarmStartCache {
    std::array<Real, 8> normalRate{};
    std::array<Vec3, 8> frictionRate{};
    /// Bit i set: vertex i was in resting contact.
    std::uint8_t vertices = 0;
};

/// Which stage of the step solved a contact (docs/physics/README.md, the step).
enum class ContactPhase : std::uint8_t { Impact, Resting, Average };

/// "impact", "resting" or "average".
const char* contactPhaseName(ContactPhase phase);

/// One contact solve of one body, for the contact ledger (WorldSettings::recordContacts).
struct ContactRecord {
    /// Simulated time of the solve (the start of its sub-step), s.
    Real time = 0.0;
    ContactPhase phase = ContactPhase::Resting;
    /// The body's centre of mass when the solve ran (the points' offsets are from it), m.
    Vec3 centreOfMass{0.0};
    /// The points with their impulses and their velocities before and after.
    ContactManifold manifold{};
};

/// An impact of a body on the ground: the contact and the impulses that resolved it.
struct CollisionEvent {
    /// Simulated time of the impact, s.
    Real time = 0.0;
    ContactManifold manifold{};
    /// Most negative normal velocity of a touching vertex before the impact, m/s.
    Real approachSpeed = 0.0;
    /// Sum of the normal impulses, world frame, N s.
    Vec3 normalImpulse{0.0};
    /// Sum of the friction impulses, world frame, N s.
    Vec3 frictionImpulse{0.0};
    /// False when the approach was slower than the restitution threshold (a plastic impact).
    bool restitutionApplied = false;
    /// The coefficient of restitution of the impact (the pair's, (11.7)); 0 makes an impact
    /// plastic even when restitution applies.
    Real restitution = 0.0;
    /// Kinetic energy just before and just after the impact, J.
    Real kineticEnergyBefore = 0.0;
    Real kineticEnergyAfter = 0.0;
};

} // namespace tumble
