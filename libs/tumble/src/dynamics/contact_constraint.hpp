// What the island solver works on: per-step velocity state of the bodies of an island, and the
// two-body rows of one contact point (docs/physics/11-island-solver.md).
#pragma once

#include "tumble/contact.hpp"
#include "tumble/math.hpp"

#include <array>
#include <cstdint>

namespace tumble {

/// A body as the solver sees it: velocities and inverse mass properties. Static geometry is the
/// one solver body with zero inverse mass and inertia, which no impulse moves.
struct SolverBody {
    Vec3 linearVelocity{0.0};
    Vec3 angularVelocity{0.0};
    Real invMass = 0.0;
    Mat3 invInertiaWorld{0.0};

    [[nodiscard]] Vec3 velocityAt(const Vec3& offset) const
    {
        return linearVelocity + glm::cross(angularVelocity, offset);
    }
};

/// One contact point between solver bodies A and B: the normal n points from A to B, and the
/// impulse P acts on B at rB and -P on A at rA (11.1).
struct ContactConstraint {
    std::uint32_t bodyA = 0;
    std::uint32_t bodyB = 0;
    /// Index of the contact (pair) and of the point in it, for warm starting and reporting.
    std::uint32_t contact = 0;
    std::uint32_t point = 0;
    Vec3 normal{0.0, 1.0, 0.0};
    Vec3 tangent1{1.0, 0.0, 0.0};
    Vec3 tangent2{0.0, 0.0, 1.0};
    Vec3 offsetA{0.0};
    Vec3 offsetB{0.0};
    /// Gap along the normal at the start of the sub-step, m (negative: penetration).
    Real separation = 0.0;
    Real normalMass = 0.0;
    /// Tangential K_t (11.3) and its inverse, row-major.
    std::array<Real, 4> tangentK{};
    std::array<Real, 4> tangentMass{};
    /// The angular rows of the Jacobian along d = n, t1, t2 (11.2): rA x d and rB x d, and their
    /// images under the inverse inertia, IA^-1 (rA x d) and IB^-1 (rB x d). With them a sweep
    /// reads the point velocity along d as d . v + (r x d) . w and applies an impulse as a
    /// scaled sum, without cross products or matrix products.
    std::array<Vec3, 3> angularA{};
    std::array<Vec3, 3> angularB{};
    std::array<Vec3, 3> responseA{};
    std::array<Vec3, 3> responseB{};
    /// Each body's part of K (11.2), (11.3): along n, and the tangential (t1 t1, t1 t2, t2 t2);
    /// the work of an impulse on one body follows from them (8.2).
    Real normalKA = 0.0;
    Real normalKB = 0.0;
    std::array<Real, 3> tangentKA{};
    std::array<Real, 3> tangentKB{};
    /// The pair's kinetic and static coefficients, and the one this solve uses (6.2).
    Real kineticFriction = 0.0;
    Real staticFriction = 0.0;
    Real friction = 0.0;
    Real restitution = 0.0;
    /// Lowest normal velocity the solve allows: -e vn for an impact, 0 in contact, -gap / tau
    /// for a point still apart (11.4).
    Real targetNormalVelocity = 0.0;
    /// Relative velocity u and its normal part when the constraint was prepared, m/s.
    Vec3 velocityBefore{0.0};
    Real normalVelocityBefore = 0.0;
    Real normalImpulse = 0.0;
    Real tangentImpulse1 = 0.0;
    Real tangentImpulse2 = 0.0;
    /// Where the friction step's Newton iteration (6.4) starts: last sweep's shift.
    Real frictionShift = 0.0;
    /// Work of this point's normal and friction impulses on its two bodies since the
    /// constraint was prepared (warm start and sweeps), J: each step's P . (u_before +
    /// u_after) / 2 with u the relative velocity (08-energy-ledger.md, (8.2)).
    Real normalWork = 0.0;
    Real frictionWork = 0.0;
    RestitutionState restitutionState = RestitutionState::None;
};

} // namespace tumble
