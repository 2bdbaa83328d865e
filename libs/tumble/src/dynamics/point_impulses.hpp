// One contact point's impulses on its two solver bodies, and the work they do: the steps that
// warm starting, restitution and the sweeps are made of (docs/physics/11-island-solver.md).
#pragma once

#include "dynamics/contact_constraint.hpp"
#include "dynamics/friction_cone.hpp"

#include <array>

namespace tumble {

/// The point velocity of a body along direction d of a constraint, d . v + (r x d) . w (11.2),
/// from the constraint's angular row `angular` = r x d.
inline Real pointVelocityAlong(const SolverBody& body, const Vec3& direction, const Vec3& angular)
{
    return glm::dot(direction, body.linearVelocity) + glm::dot(angular, body.angularVelocity);
}

/// The direction of row 0, 1, 2 of a constraint: n, t1, t2.
inline const Vec3& directionOf(const ContactConstraint& c, int axis)
{
    return axis == 0 ? c.normal : (axis == 1 ? c.tangent1 : c.tangent2);
}

/// The relative point velocity u = vB - vA along row `axis` of a constraint, the row of J times
/// the bodies' velocities (11.2).
inline Real rowVelocity(const ContactConstraint& c, const SolverBody& a, const SolverBody& b,
                        int axis)
{
    const Vec3& d = directionOf(c, axis);
    return pointVelocityAlong(b, d, c.angularB[axis]) - pointVelocityAlong(a, d, c.angularA[axis]);
}

/// Whether a solver body is the island's static geometry, which no impulse moves. Its state is
/// never written, so the points of one colour may share it across threads (11.5c).
inline bool isFixed(const SolverBody& body) { return body.invMass == 0.0; }

/// Applies `impulse` times direction d (index `axis`: n, t1, t2) to B and its opposite to A.
inline void applyAlong(const ContactConstraint& c, SolverBody& a, SolverBody& b,
                       const Vec3& direction, int axis, Real impulse)
{
    if (!isFixed(a)) {
        a.linearVelocity -= (a.invMass * impulse) * direction;
        a.angularVelocity -= impulse * c.responseA[axis];
    }
    if (!isFixed(b)) {
        b.linearVelocity += (b.invMass * impulse) * direction;
        b.angularVelocity += impulse * c.responseB[axis];
    }
}

/// The normal step of one point: impulse change `change` along n, from point velocities vA and
/// vB along n before it. Books its work on the pair, P . (u_before + u_after) / 2 (8.2), with
/// u = vB - vA and u_after = u_before + change (kA + kB).
inline void applyNormal(ContactConstraint& c, SolverBody& a, SolverBody& b, Real change, Real vA,
                        Real vB)
{
    applyAlong(c, a, b, c.normal, 0, change);
    c.normalWork += change * (vB - vA + 0.5 * change * (c.normalKA + c.normalKB));
}

/// The friction step of one point: impulse change (change1, change2) along t1, t2, from point
/// velocities along t1, t2 before it (A's, then B's); its work on the pair as in applyNormal
/// with the pair's 2x2 K_t.
inline void applyFriction(ContactConstraint& c, SolverBody& a, SolverBody& b, Real change1,
                          Real change2, const std::array<Real, 4>& velocities)
{
    applyAlong(c, a, b, c.tangent1, 1, change1);
    applyAlong(c, a, b, c.tangent2, 2, change2);
    const Real along1 = velocities[2] - velocities[0] +
                        0.5 * (c.tangentK[0] * change1 + c.tangentK[1] * change2);
    const Real along2 = velocities[3] - velocities[1] +
                        0.5 * (c.tangentK[2] * change1 + c.tangentK[3] * change2);
    c.frictionWork += change1 * along1 + change2 * along2;
}

/// Sets a constraint's starting impulses (warm starting, (11.6)): the normal one, and the friction
/// one along t1, t2 kept in the cone of the point's coefficient (set with its targets) (6.2).
inline void startInCone(ContactConstraint& c, Real normal, Real tangent1, Real tangent2)
{
    c.normalImpulse = normal;
    const FrictionImpulse inCone = scaledIntoDisc(tangent1, tangent2, c.friction * normal);
    c.tangentImpulse1 = inCone.impulse1;
    c.tangentImpulse2 = inCone.impulse2;
}

/// Applies a point's whole cached impulse (warm starting, (11.6)) as one impulse P = J^T lambda:
/// P on B's centre and its moment rB x P = sum_i lambda_i (rB x d_i) (A's opposite), so each
/// body's velocities change once. Its work on the pair is booked under the normal heading,
/// P . (u_before + u_after) / 2 (8.2), with P . u = P . (vB - vA) + (rB x P) . wB - (rA x P) . wA.
inline void warmStartPoint(ContactConstraint& c, SolverBody& a, SolverBody& b)
{
    const Real ln = c.normalImpulse;
    const Real l1 = c.tangentImpulse1;
    const Real l2 = c.tangentImpulse2;
    const Vec3 impulse = ln * c.normal + l1 * c.tangent1 + l2 * c.tangent2;
    const Vec3 momentA = ln * c.angularA[0] + l1 * c.angularA[1] + l2 * c.angularA[2];
    const Vec3 momentB = ln * c.angularB[0] + l1 * c.angularB[1] + l2 * c.angularB[2];
    const auto relativeWork = [&] {
        return glm::dot(impulse, b.linearVelocity - a.linearVelocity) +
               glm::dot(momentB, b.angularVelocity) - glm::dot(momentA, a.angularVelocity);
    };
    const Real before = relativeWork();
    if (!isFixed(a)) {
        a.linearVelocity -= a.invMass * impulse;
        a.angularVelocity -= ln * c.responseA[0] + l1 * c.responseA[1] + l2 * c.responseA[2];
    }
    if (!isFixed(b)) {
        b.linearVelocity += b.invMass * impulse;
        b.angularVelocity += ln * c.responseB[0] + l1 * c.responseB[1] + l2 * c.responseB[2];
    }
    c.normalWork += 0.5 * (before + relativeWork());
}

} // namespace tumble
