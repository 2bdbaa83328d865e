// Per-vertex data of a solve at the touching vertices of one cuboid on the ground, and the frame
// of the solve (docs/physics/05-normal-impulse.md, 06-friction.md).
#pragma once

#include "tumble/contact.hpp"
#include "tumble/math.hpp"

#include <array>
#include <cmath>

namespace tumble {

/// Below this sliding speed a vertex sticks, and the static coefficient bounds its friction, m/s.
/// Compared as squares: the square root was a tenth of preparing a point.
inline constexpr Real kStickingSpeed = 1e-3;
inline constexpr Real kStickingSpeedSquared = kStickingSpeed * kStickingSpeed;

/// Length of (a, b). Impulses and velocities are far from overflow, so this skips the scaling
/// std::hypot does (which made it the solver's single largest cost).
inline Real planarLength(Real a, Real b) { return std::sqrt(a * a + b * b); }

/// Per-vertex data of a solve: the offset, the effective masses and the accumulated impulses
/// (symbols of docs/physics/05-normal-impulse.md and 06-friction.md). No member initialisers, so
/// a solve's unused points cost nothing; preparePoint writes every field of the ones it uses.
struct SolverPoint {
    Vec3 r;
    /// I^-1 (r x n), I^-1 (r x t1), I^-1 (r x t2): the change of angular velocity per unit
    /// impulse along each direction, computed once so a sweep applies an impulse with two
    /// scaled additions instead of a cross product and a matrix product (Catto 2005).
    Vec3 angularPerNormal;
    Vec3 angularPerTangent1;
    Vec3 angularPerTangent2;
    Real normalMass;
    /// The 2x2 tangential matrix K_t (6.3) and its inverse, the effective mass; row-major.
    std::array<Real, 4> tangentK;
    std::array<Real, 4> tangentMass;
    /// Target normal velocity: -e vn^- for an impact faster than the threshold, else 0 (5.3).
    Real targetNormalVelocity;
    Real friction;
    /// Velocity of the material point at the vertex when the solve was prepared.
    Vec3 velocityBefore;
    RestitutionState restitution;
    Real normalImpulse;
    Real tangentImpulse1;
    Real tangentImpulse2;
    /// The shift s of the last friction solve on the cone's edge (6.4), where the next sweep's
    /// Newton iteration starts: the edge solution moves little from sweep to sweep.
    Real frictionShift;
};

struct SolverFrame {
    Vec3 n{0.0, 1.0, 0.0};
    Vec3 t1{1.0, 0.0, 0.0};
    Vec3 t2{0.0, 0.0, 1.0};
};

inline SolverFrame makeFrame(const Vec3& normal)
{
    SolverFrame frame;
    frame.n = normal;
    orthonormalBasis(normal, frame.t1, frame.t2);
    return frame;
}

} // namespace tumble
