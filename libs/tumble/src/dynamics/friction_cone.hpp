// The maximal-dissipation friction impulse of one contact point on its Coulomb cone
// (docs/physics/06-friction.md, (6.4)).
#pragma once

#include "tumble/math.hpp"

#include <array>
#include <cmath>

namespace tumble {

struct FrictionImpulse {
    Real impulse1 = 0.0;
    Real impulse2 = 0.0;
};

/// (6.2): a friction impulse outside the disc |lambda| <= bound scaled back onto its edge, along
/// its own direction (a zero bound gives zero); inside the disc it is kept as it is.
inline FrictionImpulse scaledIntoDisc(Real impulse1, Real impulse2, Real bound)
{
    const Real magnitude = std::sqrt(impulse1 * impulse1 + impulse2 * impulse2);
    if (magnitude <= bound) {
        return {impulse1, impulse2};
    }
    const Real scale = magnitude > 0.0 ? bound / magnitude : 0.0;
    return {scale * impulse1, scale * impulse2};
}

/// The friction impulse of one point with the others held fixed (6.4): the impulse in the disc
/// |lambda| <= bound that minimises the kinetic energy, lambda^T K lambda / 2 + lambda^T v_free,
/// where v_free is the tangential velocity (v1, v2) without this point's current friction
/// (current1, current2). Inside the disc it stops the sliding; on its edge it is
/// -(K + s 1)^-1 v_free with s >= 0 such that |lambda| = bound, which leaves the remaining
/// sliding exactly opposite to it (maximal dissipation). `tangentK` and `tangentMass` are K_t
/// and its inverse (6.3), row-major; `shift` is where Newton's method on s starts, and is left
/// at the solution for the next call.
FrictionImpulse frictionOnCone(const std::array<Real, 4>& tangentK,
                               const std::array<Real, 4>& tangentMass, Real current1,
                               Real current2, Real bound, Real v1, Real v2, Real& shift);

} // namespace tumble
