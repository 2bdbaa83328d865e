// The soft step's rows: the springs' coefficients and each manifold's rows at the step's start
// (docs/physics/12-soft-step.md, (12.2), (12.3), (12.5)).
#include "dynamics/soft_contact_solver.hpp"

#include <cmath>
#include <numbers>

namespace tumble {

Softness makeSoftness(Real hertz, Real dampingRatio, Real h)
{
    if (hertz == 0.0) {
        return {};
    }
    // implicit Euler on m x'' = -k x - c x' with k = m omega^2, c = 2 m zeta omega (12.2)
    const Real omega = 2.0 * std::numbers::pi * hertz;
    const Real a1 = 2.0 * dampingRatio + h * omega;
    const Real a2 = h * omega * a1;
    const Real a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

void centreSoftManifold(SoftManifold& m)
{
    Vec3 sumA(0.0);
    Vec3 sumB(0.0);
    for (int k = 0; k < m.pointCount; ++k) {
        sumA += m.points[k].anchorA;
        sumB += m.points[k].anchorB;
    }
    const Real count = m.pointCount > 0 ? static_cast<Real>(m.pointCount) : 1.0;
    m.centreA = sumA / count;
    m.centreB = sumB / count;
}

void prepareSoftRows(SoftManifold& m, std::span<const SoftBody> bodies)
{
    const SoftBody& a = bodies[m.bodyA];
    const SoftBody& b = bodies[m.bodyB];
    centreSoftManifold(m);
    for (int k = 0; k < m.pointCount; ++k) {
        SoftPoint& p = m.points[k];
        p.angularA = glm::cross(p.anchorA, m.normal);
        p.angularB = glm::cross(p.anchorB, m.normal);
        p.responseA = a.invInertia * p.angularA;
        p.responseB = b.invInertia * p.angularB;
        // (11.2): K = mA + mB + (rA x n) . IA^-1 (rA x n) + (rB x n) . IB^-1 (rB x n)
        const Real kn = a.invMass + b.invMass + glm::dot(p.angularA, p.responseA) +
                       glm::dot(p.angularB, p.responseB);
        p.normalK = kn;
        p.normalMass = kn > 0.0 ? 1.0 / kn : 0.0;
        const Vec3 fromCentre = m.points[k].anchorB - m.centreB;
        m.points[k].leverArm = glm::length(fromCentre - glm::dot(fromCentre, m.normal) * m.normal);
    }
    // (12.4): how each point's impulse moves the others' normal velocities
    for (int i = 0; i < m.pointCount; ++i) {
        for (int j = i + 1; j < m.pointCount; ++j) {
            const SoftPoint& p = m.points[i];
            const SoftPoint& q = m.points[j];
            m.normalCoupling[couplingIndex(i, j)] = a.invMass + b.invMass +
                                                    glm::dot(p.angularA, q.responseA) +
                                                    glm::dot(p.angularB, q.responseB);
        }
    }
    const Vec3 angularA1 = glm::cross(m.centreA, m.tangent1);
    const Vec3 angularA2 = glm::cross(m.centreA, m.tangent2);
    const Vec3 angularB1 = glm::cross(m.centreB, m.tangent1);
    const Vec3 angularB2 = glm::cross(m.centreB, m.tangent2);
    const Vec3 responseA1 = a.invInertia * angularA1;
    const Vec3 responseA2 = a.invInertia * angularA2;
    const Vec3 responseB1 = b.invInertia * angularB1;
    const Vec3 responseB2 = b.invInertia * angularB2;
    m.twistResponseA = a.invInertia * m.normal;
    m.twistResponseB = b.invInertia * m.normal;
    // (11.3) at the centre: K_ij = (mA + mB) t_i . t_j + (cA x t_i) . IA^-1 (cA x t_j) + ...
    const Real massSum = a.invMass + b.invMass;
    const Real k11 = massSum + glm::dot(angularA1, responseA1) +
                     glm::dot(angularB1, responseB1);
    const Real k12 = glm::dot(angularA1, responseA2) + glm::dot(angularB1, responseB2);
    const Real k22 = massSum + glm::dot(angularA2, responseA2) +
                     glm::dot(angularB2, responseB2);
    m.tangentK = {k11, k12, k22};
    const Real determinant = k11 * k22 - k12 * k12;
    m.tangentMass = determinant > 0.0 ? std::array<Real, 3>{k22 / determinant,
                                                            -k12 / determinant,
                                                            k11 / determinant}
                                      : std::array<Real, 3>{};
    m.twistK = glm::dot(m.normal, m.twistResponseA) + glm::dot(m.normal, m.twistResponseB);
    m.twistMass = m.twistK > 0.0 ? 1.0 / m.twistK : 0.0;
}

} // namespace tumble
