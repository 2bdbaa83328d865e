// BodyDef (what a user asks for) and Body (the read-only state a World keeps for each body).
#pragma once

#include "tumble/energy_ledger.hpp"
#include "tumble/material.hpp"
#include "tumble/math.hpp"
#include "tumble/shape.hpp"

#include <cstdint>

namespace tumble {

/// Whether a body moves. A static body is fixed geometry (a wall, a tray, a step): no mass, no
/// velocity, never moved by gravity or contact; it joins no island (docs/physics/10-broad-phase.md).
enum class BodyMotion : std::uint8_t { Dynamic, Static };

/// Everything needed to create a cuboid body; copied in by World::createBody.
struct BodyDef {
    /// Default BodyMotion::Dynamic.
    BodyMotion motion = BodyMotion::Dynamic;
    /// The cuboid. Default: the 2 x 2 x 2 cube.
    Cuboid shape{};
    /// Mass, kg, > 0. Default 1.
    Real mass = 1.0;
    /// Centre of mass in world coordinates, m. Default origin.
    Vec3 position{0.0};
    /// Unit quaternion from body to world axes. Default identity.
    Quat orientation{1.0, 0.0, 0.0, 0.0};
    /// Velocity of the centre of mass, world frame, m/s. Default 0.
    Vec3 linearVelocity{0.0};
    /// Angular velocity, world frame, rad/s. Default 0.
    Vec3 angularVelocity{0.0};
    /// Restitution and friction. Default Material{}.
    Material material{};
    /// False for a static body that gives no material of its own: its contacts then take the
    /// dynamic body's (docs/physics/11-island-solver.md, (11.7)). Default true.
    bool materialGiven = true;
};

/// State of one body as World keeps it. Users read it through World::body(id) and change it
/// through World's setters, which keep the derived quantities (inverse inertia) consistent.
struct Body {
    BodyMotion motion = BodyMotion::Dynamic;
    Cuboid shape{};
    Real mass = 1.0;
    Real invMass = 1.0;
    /// Diagonal of the body-frame inverse inertia I0^-1, recomputed when mass or size change.
    Vec3 invInertiaBody{0.0};
    /// World-frame inverse inertia R I0^-1 R^T, recomputed when the orientation changes.
    Mat3 invInertiaWorld{0.0};
    Vec3 position{0.0};
    Quat orientation{1.0, 0.0, 0.0, 0.0};
    Vec3 linearVelocity{0.0};
    Vec3 angularVelocity{0.0};
    Material material{};
    /// See BodyDef::materialGiven.
    bool materialGiven = true;
    /// True once the body has stayed slow in contact for WorldSettings::sleepTime; a sleeping
    /// body is not integrated until something wakes it.
    bool asleep = false;
    /// How long the body has been slow in contact with the ground, s.
    Real slowTime = 0.0;
    /// Where the body's energy went since its creation.
    EnergyLedger ledger{};

    [[nodiscard]] bool isStatic() const { return motion == BodyMotion::Static; }
    [[nodiscard]] Mat3 rotation() const { return glm::mat3_cast(orientation); }
    /// Body-frame inertia diagonal I0, kg m^2.
    [[nodiscard]] Vec3 inertiaBody() const { return cuboidInertiaDiagonal(mass, shape.size); }
    /// World-frame inertia tensor R I0 R^T.
    [[nodiscard]] Mat3 inertiaWorld() const
    {
        return rotateDiagonalTensor(rotation(), inertiaBody());
    }
    /// Angular momentum about the centre of mass, world frame: L = I w.
    [[nodiscard]] Vec3 angularMomentum() const { return inertiaWorld() * angularVelocity; }
    /// Linear momentum m v.
    [[nodiscard]] Vec3 linearMomentum() const { return mass * linearVelocity; }
    /// Translational plus rotational kinetic energy, J. The rotational part w . I w / 2 is
    /// taken in the body frame, sum_k I0_k (R^T w)_k^2 / 2: one quaternion rotation instead of
    /// building R I0 R^T (the ledger asks for it several times per sub-step).
    [[nodiscard]] Real kineticEnergy() const
    {
        const Vec3 bodySpin = glm::conjugate(orientation) * angularVelocity;
        return 0.5 * mass * lengthSquared(linearVelocity) +
               0.5 * glm::dot(inertiaBody() * bodySpin, bodySpin);
    }
    /// Potential energy in a uniform gravity field, J, zero at the world origin: -m g . x.
    [[nodiscard]] Real potentialEnergy(const Vec3& gravity) const
    {
        // 0 - x, not -x: a body at the origin has potential energy +0, never -0 in the output
        return 0.0 - mass * glm::dot(gravity, position);
    }
    /// Velocity of the material point at `worldPoint`: v + w x r.
    [[nodiscard]] Vec3 velocityAt(const Vec3& worldPoint) const
    {
        return linearVelocity + glm::cross(angularVelocity, worldPoint - position);
    }
    /// World coordinates of the point with body coordinates `localPoint`.
    [[nodiscard]] Vec3 worldPoint(const Vec3& localPoint) const
    {
        return position + orientation * localPoint;
    }
};

} // namespace tumble
