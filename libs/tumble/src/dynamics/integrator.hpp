// Free-flight integration: torque-free rotation and constant-acceleration translation
// (docs/physics/02-integration.md).
#pragma once

#include <limits>

#include "tumble/body.hpp"
#include "tumble/math.hpp"
#include "tumble/settings.hpp"

namespace tumble {

/// Torque-free rotation over dt. Integrator::Exact conserves the world angular momentum
/// (2.4)-(2.7); Integrator::Handout is R += dt [w]x R with w constant (2.8).
void integrateRotation(Quat& orientation, Vec3& angularVelocity, const Vec3& inertiaBody, Real dt,
                       Integrator integrator);

/// Bounds on how the pose integrateRotation gives after a step of length s changes with s, for
/// every s in [0, maxStep] (used by the time of impact, docs/physics/04-detection.md):
/// - (4.4) the rates, rad/s, at which the pieces of the pose turn, sorted by the axis they turn
///   about: an axis that may point anywhere (the momentum Pi, or a handout rotation about w),
///   and the body's own near and far axes of the split (2.7), whose vertices stay close to those
///   axes for a long thin body;
/// - (4.4a) where the pose is the exact torque-free flow (Integrator::Exact and two or three
///   equal moments), |dw/ds| + |w|^2 along it, 1/s^2: a material point at offset r then
///   accelerates by at most that times |r|. Infinity for the other poses, whose second
///   derivative in s has no such simple bound.
struct RotationBounds {
    Real aboutAnyAxis = 0.0;
    Real aboutNearAxis = 0.0;
    Real aboutFarAxis = 0.0;
    int nearAxis = 1;
    int farAxis = 2;
    Real curvature = std::numeric_limits<Real>::infinity();

    [[nodiscard]] Real total() const { return aboutAnyAxis + aboutNearAxis + aboutFarAxis; }
};
RotationBounds rotationBounds(const Quat& orientation, const Vec3& angularVelocity,
                              const Vec3& inertiaBody, Real maxStep, Integrator integrator);

/// (2.7b): a bound on how far the kinetic energy of Integrator::Exact can move from its start
/// value over torque-free rotation in steps of length h, to leading order in h, J: the splitting
/// conserves a modified energy within 4 h^2 |Pi|^4 |c_near c_far| (|c_near| / 96 + |c_far| / 48)
/// of the true one (docs/physics/02-integration.md). Zero for a symmetric body, whose split is
/// exact.
Real rotationEnergyErrorBound(const Quat& orientation, const Vec3& angularVelocity,
                              const Vec3& inertiaBody, Real h);

/// Same, on a body, keeping its world inverse inertia consistent with the new orientation.
void integrateRotation(Body& body, Real dt, Integrator integrator);

/// Position of the centre of mass after time s of a sub-step of length tau in which the velocity
/// changes uniformly from velocityStart to velocityEnd (2.2): exact under constant gravity.
inline Vec3 positionAfter(const Vec3& position, const Vec3& velocityStart, const Vec3& velocityEnd,
                          Real tau, Real s)
{
    const Vec3 acceleration = (velocityEnd - velocityStart) / tau;
    return position + s * velocityStart + (0.5 * s * s) * acceleration;
}

} // namespace tumble
