// Two-body sequential impulses with accumulated clamping and a friction disc (Catto 2005, 2014).
#include "dynamics/island_solver.hpp"

#include "dynamics/friction_cone.hpp"

#include <algorithm>
#include <cmath>

namespace tumble {

namespace {

/// Below this sliding speed a point sticks, and the static coefficient bounds its friction, m/s.
constexpr Real kStickingSpeed = 1e-3;

/// K along directions d1, d2 of a constraint (11.2), (11.3):
/// 1/mA + 1/mB + (rA x d1) . IA^-1 (rA x d2) + (rB x d1) . IB^-1 (rB x d2).
Real effectiveInverseMass(const ContactConstraint& c, const SolverBody& a, const SolverBody& b,
                          const Vec3& d1, const Vec3& d2)
{
    const Vec3 a1 = glm::cross(c.offsetA, d1);
    const Vec3 b1 = glm::cross(c.offsetB, d1);
    const Vec3 a2 = glm::cross(c.offsetA, d2);
    const Vec3 b2 = glm::cross(c.offsetB, d2);
    const Real linear = glm::dot(d1, d2) * (a.invMass + b.invMass);
    return linear + glm::dot(a1, a.invInertiaWorld * a2) + glm::dot(b1, b.invInertiaWorld * b2);
}

/// Velocity of B's material point relative to A's at the constraint's point.
Vec3 relativeVelocity(const ContactConstraint& c, const SolverBody& a, const SolverBody& b)
{
    return b.velocityAt(c.offsetB) - a.velocityAt(c.offsetA);
}

/// Applies impulse P to B and -P to A at the constraint's point, and books its work on each
/// body, P . (u_before + u_after) / 2 per body (8.2), under the normal or the friction heading.
void applyImpulse(const ContactConstraint& c, SolverBody& a, SolverBody& b, const Vec3& impulse,
                  bool isFriction)
{
    const Real beforeA = glm::dot(impulse, a.velocityAt(c.offsetA));
    const Real beforeB = glm::dot(impulse, b.velocityAt(c.offsetB));
    a.linearVelocity -= a.invMass * impulse;
    a.angularVelocity -= a.invInertiaWorld * glm::cross(c.offsetA, impulse);
    b.linearVelocity += b.invMass * impulse;
    b.angularVelocity += b.invInertiaWorld * glm::cross(c.offsetB, impulse);
    const Real workA = -0.5 * (beforeA + glm::dot(impulse, a.velocityAt(c.offsetA)));
    const Real workB = 0.5 * (beforeB + glm::dot(impulse, b.velocityAt(c.offsetB)));
    (isFriction ? a.frictionWork : a.normalWork) += workA;
    (isFriction ? b.frictionWork : b.normalWork) += workB;
}

} // namespace

void prepareConstraint(ContactConstraint& c, std::span<const SolverBody> bodies,
                       const ConstraintTargetSettings& settings)
{
    const SolverBody& a = bodies[c.bodyA];
    const SolverBody& b = bodies[c.bodyB];
    orthonormalBasis(c.normal, c.tangent1, c.tangent2);
    c.normalMass = 1.0 / effectiveInverseMass(c, a, b, c.normal, c.normal);
    const Real k11 = effectiveInverseMass(c, a, b, c.tangent1, c.tangent1);
    const Real k22 = effectiveInverseMass(c, a, b, c.tangent2, c.tangent2);
    const Real k12 = effectiveInverseMass(c, a, b, c.tangent1, c.tangent2);
    const Real invDeterminant = 1.0 / (k11 * k22 - k12 * k12);
    c.tangentK = {k11, k12, k12, k22};
    c.tangentMass = {k22 * invDeterminant, -k12 * invDeterminant, -k12 * invDeterminant,
                     k11 * invDeterminant};
    const Vec3 velocity = relativeVelocity(c, a, b);
    const Real normalVelocity = glm::dot(c.normal, velocity);
    c.velocityBefore = velocity;
    c.normalVelocityBefore = normalVelocity;
    const Vec3 sliding = velocity - normalVelocity * c.normal;
    const bool sticking = lengthSquared(sliding) < kStickingSpeed * kStickingSpeed;
    c.friction = sticking ? c.staticFriction : c.kineticFriction;
    c.restitutionState = RestitutionState::None;
    c.targetNormalVelocity = 0.0;
    if (settings.target == ConstraintTarget::Substep) {
        // (11.4): a point still apart may close its gap within the sub-step, not cross it
        if (c.separation > settings.touchingGap) {
            c.targetNormalVelocity = -c.separation / settings.tau;
        }
        return;
    }
    // (11.4), Newton's law of restitution (5.3) for the impact
    if (normalVelocity < -settings.restitutionThreshold) {
        c.targetNormalVelocity = -c.restitution * normalVelocity;
        c.restitutionState = RestitutionState::Applied;
    } else if (normalVelocity < 0.0 && c.restitution > 0.0) {
        c.restitutionState = RestitutionState::Suppressed;
    }
}

void applyRestitution(std::span<ContactConstraint> constraints, std::span<SolverBody> bodies)
{
    for (ContactConstraint& c : constraints) {
        if (c.restitutionState != RestitutionState::Applied) {
            continue;
        }
        const Real extra = c.restitution * c.normalImpulse;
        c.normalImpulse += extra;
        applyImpulse(c, bodies[c.bodyA], bodies[c.bodyB], extra * c.normal, false);
    }
}

void warmStart(std::span<const ContactConstraint> constraints, std::span<SolverBody> bodies)
{
    for (const ContactConstraint& c : constraints) {
        const Vec3 impulse = c.normalImpulse * c.normal + c.tangentImpulse1 * c.tangent1 +
                             c.tangentImpulse2 * c.tangent2;
        applyImpulse(c, bodies[c.bodyA], bodies[c.bodyB], impulse, false);
    }
}

int solveConstraints(std::span<ContactConstraint> constraints, std::span<SolverBody> bodies,
                     int iterations, Real convergence)
{
    for (int sweep = 1; sweep <= iterations; ++sweep) {
        Real largestChange = 0.0;
        Real largestImpulse = 0.0;
        for (ContactConstraint& c : constraints) {
            SolverBody& a = bodies[c.bodyA];
            SolverBody& b = bodies[c.bodyB];
            // (11.4): normal impulse with accumulated clamping, lambda_n >= 0
            const Real normalVelocity = glm::dot(c.normal, relativeVelocity(c, a, b));
            const Real normalImpulse = std::max(
                0.0, c.normalImpulse + c.normalMass * (c.targetNormalVelocity - normalVelocity));
            const Real normalChange = normalImpulse - c.normalImpulse;
            c.normalImpulse = normalImpulse;
            applyImpulse(c, a, b, normalChange * c.normal, false);
            // (11.5): the friction step of maximal dissipation on the cone (6.4)
            const Vec3 velocity = relativeVelocity(c, a, b);
            const FrictionImpulse friction = frictionOnCone(
                c.tangentK, c.tangentMass, c.tangentImpulse1, c.tangentImpulse2,
                c.friction * c.normalImpulse, glm::dot(c.tangent1, velocity),
                glm::dot(c.tangent2, velocity), c.frictionShift);
            const Real impulse1 = friction.impulse1;
            const Real impulse2 = friction.impulse2;
            const Real magnitude = std::sqrt(impulse1 * impulse1 + impulse2 * impulse2);
            const Real change1 = impulse1 - c.tangentImpulse1;
            const Real change2 = impulse2 - c.tangentImpulse2;
            c.tangentImpulse1 = impulse1;
            c.tangentImpulse2 = impulse2;
            applyImpulse(c, a, b, change1 * c.tangent1 + change2 * c.tangent2, true);
            largestChange = std::max(
                {largestChange, std::abs(normalChange), std::abs(change1), std::abs(change2)});
            largestImpulse = std::max({largestImpulse, normalImpulse, magnitude});
        }
        if (largestChange <= convergence * largestImpulse) {
            return sweep;
        }
    }
    return iterations;
}

} // namespace tumble
