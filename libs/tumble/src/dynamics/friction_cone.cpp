// Maximal-dissipation friction on the Coulomb cone (6.4).
#include "dynamics/friction_cone.hpp"

#include <algorithm>
#include <cmath>

namespace tumble {

namespace {

/// Length of (a, b). Impulses and velocities are far from overflow, so this skips the scaling
/// std::hypot does.
Real planarLength(Real a, Real b) { return std::sqrt(a * a + b * b); }

} // namespace

FrictionImpulse frictionOnCone(const std::array<Real, 4>& k,
                               const std::array<Real, 4>& tangentMass, Real current1,
                               Real current2, Real bound, Real v1, Real v2, Real& shift)
{
    const Real free1 = v1 - (k[0] * current1 + k[1] * current2);
    const Real free2 = v2 - (k[2] * current1 + k[3] * current2);
    FrictionImpulse result;
    result.impulse1 = -(tangentMass[0] * free1 + tangentMass[1] * free2);
    result.impulse2 = -(tangentMass[2] * free1 + tangentMass[3] * free2);
    const Real freeMagnitude = planarLength(result.impulse1, result.impulse2);
    if (freeMagnitude <= bound) {
        return result;
    }
    // a bound negligible next to the free impulse (zero, or a subnormal coefficient) is no
    // friction: Newton's method below would overflow 1/bound
    if (bound <= 1e-15 * freeMagnitude) {
        return FrictionImpulse{};
    }
    // Newton's method on 1/|lambda(s)| - 1/bound, concave and increasing in s, converges from
    // any s >= 0 without overshooting the root from the left. With D = det(K + s 1) and
    // m = adj(K + s 1) v_free the impulse is -m / D, so |lambda| = |m| / D and
    // lambda^T (K + s 1)^-1 lambda = m^T adj(K + s 1) m / D^3: one division a step.
    Real scaled1 = 0.0;
    Real scaled2 = 0.0;
    Real scaledMagnitude = 0.0;
    const Real inverseBound = 1.0 / bound;
    for (int iteration = 0; iteration < 50; ++iteration) {
        const Real a = k[0] + shift;
        const Real d = k[3] + shift;
        const Real determinant = a * d - k[1] * k[1];
        scaled1 = d * free1 - k[1] * free2;
        scaled2 = a * free2 - k[1] * free1;
        scaledMagnitude = planarLength(scaled1, scaled2);
        const Real boundTimesDeterminant = bound * determinant;
        if (std::abs(scaledMagnitude - boundTimesDeterminant) <= 1e-15 * boundTimesDeterminant) {
            break;
        }
        // the step phi / phi' is |m|^2 (D - |m| / bound) / m^T adj(K + s 1) m
        const Real quadratic =
            d * scaled1 * scaled1 - 2.0 * k[1] * scaled1 * scaled2 + a * scaled2 * scaled2;
        shift = std::max(0.0, shift - scaledMagnitude * scaledMagnitude *
                                          (determinant - scaledMagnitude * inverseBound) /
                                          quadratic);
    }
    // rounding aside -m / D is on the circle; put the impulse there exactly
    const Real scale = -bound / scaledMagnitude;
    result.impulse1 = scale * scaled1;
    result.impulse2 = scale * scaled2;
    return result;
}

} // namespace tumble
