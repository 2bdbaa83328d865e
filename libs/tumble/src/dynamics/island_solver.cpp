// Two-body sequential impulses with accumulated clamping and a friction disc (Catto 2005, 2014).
#include "dynamics/island_solver.hpp"

#include "dynamics/friction_cone.hpp"
#include "dynamics/point_impulses.hpp"

#include <algorithm>
#include <cmath>

namespace tumble {

namespace {

/// Below this sliding speed a point sticks, and the static coefficient bounds its friction, m/s.
constexpr Real kStickingSpeed = 1e-3;

/// Velocity of B's material point relative to A's at the constraint's point.
Vec3 relativeVelocity(const ContactConstraint& c, const SolverBody& a, const SolverBody& b)
{
    return b.velocityAt(c.offsetB) - a.velocityAt(c.offsetA);
}

} // namespace

void prepareConstraintGeometry(ContactConstraint& c, const SolverBody& a, const SolverBody& b)
{
    orthonormalBasis(c.normal, c.tangent1, c.tangent2);
    const std::array<Vec3, 3> directions{c.normal, c.tangent1, c.tangent2};
    for (int axis = 0; axis < 3; ++axis) {
        c.angularA[axis] = glm::cross(c.offsetA, directions[axis]);
        c.angularB[axis] = glm::cross(c.offsetB, directions[axis]);
        c.responseA[axis] = a.invInertiaWorld * c.angularA[axis];
        c.responseB[axis] = b.invInertiaWorld * c.angularB[axis];
    }
    // d_i . d_j = delta_ij for the orthonormal n, t1, t2
    const auto part = [&](const std::array<Vec3, 3>& angular, const std::array<Vec3, 3>& response,
                          Real invMass, int i, int j) {
        return (i == j ? invMass : 0.0) + glm::dot(angular[i], response[j]);
    };
    c.normalKA = part(c.angularA, c.responseA, a.invMass, 0, 0);
    c.normalKB = part(c.angularB, c.responseB, b.invMass, 0, 0);
    c.tangentKA = {part(c.angularA, c.responseA, a.invMass, 1, 1),
                   part(c.angularA, c.responseA, a.invMass, 1, 2),
                   part(c.angularA, c.responseA, a.invMass, 2, 2)};
    c.tangentKB = {part(c.angularB, c.responseB, b.invMass, 1, 1),
                   part(c.angularB, c.responseB, b.invMass, 1, 2),
                   part(c.angularB, c.responseB, b.invMass, 2, 2)};
    c.normalMass = 1.0 / (c.normalKA + c.normalKB);
    const Real k11 = c.tangentKA[0] + c.tangentKB[0];
    const Real k12 = c.tangentKA[1] + c.tangentKB[1];
    const Real k22 = c.tangentKA[2] + c.tangentKB[2];
    const Real invDeterminant = 1.0 / (k11 * k22 - k12 * k12);
    c.tangentK = {k11, k12, k12, k22};
    c.tangentMass = {k22 * invDeterminant, -k12 * invDeterminant, -k12 * invDeterminant,
                     k11 * invDeterminant};
}

void prepareConstraintTargets(ContactConstraint& c, std::span<const SolverBody> bodies,
                              const ConstraintTargetSettings& settings)
{
    const SolverBody& a = bodies[c.bodyA];
    const SolverBody& b = bodies[c.bodyB];
    const Vec3 velocity = relativeVelocity(c, a, b);
    const Real normalVelocity = glm::dot(c.normal, velocity);
    c.velocityBefore = velocity;
    c.normalVelocityBefore = normalVelocity;
    const Vec3 sliding = velocity - normalVelocity * c.normal;
    const bool sticking = lengthSquared(sliding) < kStickingSpeed * kStickingSpeed;
    c.friction = sticking ? c.staticFriction : c.kineticFriction;
    c.restitutionState = RestitutionState::None;
    c.targetNormalVelocity = 0.0;
    c.normalWork = 0.0;
    c.frictionWork = 0.0;
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

void prepareConstraint(ContactConstraint& c, std::span<const SolverBody> bodies,
                       const ConstraintTargetSettings& settings)
{
    prepareConstraintGeometry(c, bodies[c.bodyA], bodies[c.bodyB]);
    prepareConstraintTargets(c, bodies, settings);
}

bool applyRestitution(std::span<ContactConstraint> constraints, std::span<SolverBody> bodies)
{
    bool applied = false;
    for (ContactConstraint& c : constraints) {
        if (c.restitutionState != RestitutionState::Applied) {
            continue;
        }
        SolverBody& a = bodies[c.bodyA];
        SolverBody& b = bodies[c.bodyB];
        const Real extra = c.restitution * c.normalImpulse;
        if (extra == 0.0) {
            continue;
        }
        applied = true;
        c.normalImpulse += extra;
        applyNormal(c, a, b, extra, pointVelocityAlong(a, c.normal, c.angularA[0]),
                    pointVelocityAlong(b, c.normal, c.angularB[0]));
    }
    return applied;
}

} // namespace tumble
