// Two-body sequential impulses with accumulated clamping and a friction disc (Catto 2005, 2014).
#include "dynamics/island_solver.hpp"

#include "dynamics/friction_cone.hpp"

#include <algorithm>
#include <cmath>

namespace tumble {

namespace {

/// Below this sliding speed a point sticks, and the static coefficient bounds its friction, m/s.
constexpr Real kStickingSpeed = 1e-3;

/// The point velocity of a body along direction `axis` of a constraint, d . v + (r x d) . w
/// (11.2), from the constraint's angular row `angular` = r x d.
Real pointVelocityAlong(const SolverBody& body, const Vec3& direction, const Vec3& angular)
{
    return glm::dot(direction, body.linearVelocity) + glm::dot(angular, body.angularVelocity);
}

/// Applies `impulse` times direction d (index `axis`: n, t1, t2) to B and its opposite to A.
void applyAlong(const ContactConstraint& c, SolverBody& a, SolverBody& b, const Vec3& direction,
                int axis, Real impulse)
{
    a.linearVelocity -= (a.invMass * impulse) * direction;
    a.angularVelocity -= impulse * c.responseA[axis];
    b.linearVelocity += (b.invMass * impulse) * direction;
    b.angularVelocity += impulse * c.responseB[axis];
}

/// The normal step of one point: impulse change `change` along n, from point velocities vA and
/// vB along n before it. Books its work on each body, P . (u_before + u_after) / 2 (8.2), with
/// u_after . n = u_before . n -+ change kA or kB.
void applyNormal(const ContactConstraint& c, SolverBody& a, SolverBody& b, Real change, Real vA,
                 Real vB)
{
    applyAlong(c, a, b, c.normal, 0, change);
    a.normalWork -= change * (vA - 0.5 * change * c.normalKA);
    b.normalWork += change * (vB + 0.5 * change * c.normalKB);
}

/// The friction step of one point: impulse change (change1, change2) along t1, t2, from point
/// velocities along t1, t2 before it (A's, then B's); its work as in applyNormal with each
/// body's 2x2 part of K_t.
void applyFriction(const ContactConstraint& c, SolverBody& a, SolverBody& b, Real change1,
                   Real change2, const std::array<Real, 4>& velocities)
{
    applyAlong(c, a, b, c.tangent1, 1, change1);
    applyAlong(c, a, b, c.tangent2, 2, change2);
    const auto halfResponse = [&](const std::array<Real, 3>& k, Real& along1, Real& along2) {
        along1 = 0.5 * (k[0] * change1 + k[1] * change2);
        along2 = 0.5 * (k[1] * change1 + k[2] * change2);
    };
    Real a1 = 0.0;
    Real a2 = 0.0;
    halfResponse(c.tangentKA, a1, a2);
    a.frictionWork -= change1 * (velocities[0] - a1) + change2 * (velocities[1] - a2);
    Real b1 = 0.0;
    Real b2 = 0.0;
    halfResponse(c.tangentKB, b1, b2);
    b.frictionWork += change1 * (velocities[2] + b1) + change2 * (velocities[3] + b2);
}

/// Velocity of B's material point relative to A's at the constraint's point.
Vec3 relativeVelocity(const ContactConstraint& c, const SolverBody& a, const SolverBody& b)
{
    return b.velocityAt(c.offsetB) - a.velocityAt(c.offsetA);
}

/// The Jacobian rows, each body's part of K and its inverse masses along n, t1, t2 (11.2),
/// (11.3), for the constraint's normal, tangents and offsets.
void prepareJacobians(ContactConstraint& c, const SolverBody& a, const SolverBody& b)
{
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

} // namespace

void prepareConstraint(ContactConstraint& c, std::span<const SolverBody> bodies,
                       const ConstraintTargetSettings& settings)
{
    const SolverBody& a = bodies[c.bodyA];
    const SolverBody& b = bodies[c.bodyB];
    orthonormalBasis(c.normal, c.tangent1, c.tangent2);
    prepareJacobians(c, a, b);
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
        SolverBody& a = bodies[c.bodyA];
        SolverBody& b = bodies[c.bodyB];
        const Real extra = c.restitution * c.normalImpulse;
        c.normalImpulse += extra;
        applyNormal(c, a, b, extra, pointVelocityAlong(a, c.normal, c.angularA[0]),
                    pointVelocityAlong(b, c.normal, c.angularB[0]));
    }
}

void warmStart(std::span<const ContactConstraint> constraints, std::span<SolverBody> bodies)
{
    // the whole cached impulse, its work booked under the normal heading as one impulse
    for (const ContactConstraint& c : constraints) {
        SolverBody& a = bodies[c.bodyA];
        SolverBody& b = bodies[c.bodyB];
        const std::array<Vec3, 3> directions{c.normal, c.tangent1, c.tangent2};
        const std::array<Real, 3> impulses{c.normalImpulse, c.tangentImpulse1, c.tangentImpulse2};
        Real workA = 0.0;
        Real workB = 0.0;
        for (int axis = 0; axis < 3; ++axis) {
            workA -= impulses[axis] * pointVelocityAlong(a, directions[axis], c.angularA[axis]);
            workB += impulses[axis] * pointVelocityAlong(b, directions[axis], c.angularB[axis]);
        }
        for (int axis = 0; axis < 3; ++axis) {
            applyAlong(c, a, b, directions[axis], axis, impulses[axis]);
        }
        for (int axis = 0; axis < 3; ++axis) {
            workA -= impulses[axis] * pointVelocityAlong(a, directions[axis], c.angularA[axis]);
            workB += impulses[axis] * pointVelocityAlong(b, directions[axis], c.angularB[axis]);
        }
        a.normalWork += 0.5 * workA;
        b.normalWork += 0.5 * workB;
    }
}

int solveConstraints(std::span<ContactConstraint> constraints, std::span<SolverBody> bodies,
                     int iterations, Real convergence, Real velocityTolerance)
{
    for (int sweep = 1; sweep <= iterations; ++sweep) {
        Real largestChange = 0.0;
        Real largestImpulse = 0.0;
        // the largest velocity correction of the sweep, |K delta lambda| (11.5a)
        Real largestCorrection = 0.0;
        for (ContactConstraint& c : constraints) {
            SolverBody& a = bodies[c.bodyA];
            SolverBody& b = bodies[c.bodyB];
            // (11.4): normal impulse with accumulated clamping, lambda_n >= 0
            const Real normalA = pointVelocityAlong(a, c.normal, c.angularA[0]);
            const Real normalB = pointVelocityAlong(b, c.normal, c.angularB[0]);
            const Real normalImpulse =
                std::max(0.0, c.normalImpulse +
                                  c.normalMass * (c.targetNormalVelocity - (normalB - normalA)));
            const Real normalChange = normalImpulse - c.normalImpulse;
            c.normalImpulse = normalImpulse;
            applyNormal(c, a, b, normalChange, normalA, normalB);
            // (11.5): the friction step of maximal dissipation on the cone (6.4)
            const std::array<Real, 4> tangential{
                pointVelocityAlong(a, c.tangent1, c.angularA[1]),
                pointVelocityAlong(a, c.tangent2, c.angularA[2]),
                pointVelocityAlong(b, c.tangent1, c.angularB[1]),
                pointVelocityAlong(b, c.tangent2, c.angularB[2])};
            const FrictionImpulse friction = frictionOnCone(
                c.tangentK, c.tangentMass, c.tangentImpulse1, c.tangentImpulse2,
                c.friction * c.normalImpulse, tangential[2] - tangential[0],
                tangential[3] - tangential[1], c.frictionShift);
            const Real impulse1 = friction.impulse1;
            const Real impulse2 = friction.impulse2;
            const Real magnitude = std::sqrt(impulse1 * impulse1 + impulse2 * impulse2);
            const Real change1 = impulse1 - c.tangentImpulse1;
            const Real change2 = impulse2 - c.tangentImpulse2;
            c.tangentImpulse1 = impulse1;
            c.tangentImpulse2 = impulse2;
            applyFriction(c, a, b, change1, change2, tangential);
            largestChange = std::max(
                {largestChange, std::abs(normalChange), std::abs(change1), std::abs(change2)});
            largestImpulse = std::max({largestImpulse, normalImpulse, magnitude});
            const Real tangential1 = c.tangentK[0] * change1 + c.tangentK[1] * change2;
            const Real tangential2 = c.tangentK[2] * change1 + c.tangentK[3] * change2;
            largestCorrection = std::max(
                {largestCorrection, std::abs(normalChange) / c.normalMass,
                 std::sqrt(tangential1 * tangential1 + tangential2 * tangential2)});
        }
        if (largestChange <= convergence * largestImpulse ||
            largestCorrection <= velocityTolerance) {
            return sweep;
        }
    }
    return iterations;
}

} // namespace tumble
