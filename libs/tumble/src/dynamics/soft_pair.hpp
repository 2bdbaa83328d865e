// A soft manifold's two bodies as its one-manifold passes see them: velocities held through its
// points, impulses applied, and how the bodies moved since the step began
// (docs/physics/12-soft-step.md, (12.3)-(12.5)). For dynamics/soft_contact_solver.cpp only.
#pragma once

#include "dynamics/soft_contact_solver.hpp"

#include <array>

namespace tumble {

/// The two bodies of a manifold, their velocities held in locals through its points and
/// written back once.
struct SoftPair {
    SoftBody& a;
    SoftBody& b;
    Vec3 vA;
    Vec3 wA;
    Vec3 vB;
    Vec3 wB;

    SoftPair(SoftBody& bodyA, SoftBody& bodyB)
        : a(bodyA), b(bodyB), vA(bodyA.linearVelocity), wA(bodyA.angularVelocity),
          vB(bodyB.linearVelocity), wB(bodyB.angularVelocity)
    {
    }

    /// The sliding velocity at the centre along t1 and t2: t_i . (vB - vA) + (c_B x t_i) . wB -
    /// (c_A x t_i) . wA (11.1).
    [[nodiscard]] Real slip(const Vec3& tangent, const Vec3& angularA, const Vec3& angularB) const
    {
        return glm::dot(tangent, vB - vA) + glm::dot(angularB, wB) - glm::dot(angularA, wA);
    }

    /// The friction impulse d1 t1 + d2 t2 at the centre, through its rows' images under the
    /// inverse inertias.
    void applyFriction(const SoftManifold& m, Real d1, Real d2)
    {
        const Vec3 impulse = d1 * m.tangent1 + d2 * m.tangent2;
        vA -= a.invMass * impulse;
        wA -= a.invInertia * (d1 * m.angularA1 + d2 * m.angularA2);
        vB += b.invMass * impulse;
        wB += b.invInertia * (d1 * m.angularB1 + d2 * m.angularB2);
    }

    /// The normal impulses of a manifold's points at once: their sum along n, and the sum of
    /// their moments r x n through each inverse inertia (one product a side, not one a point).
    void applyNormals(const SoftManifold& m, const std::array<Real, 4>& impulse)
    {
        Real total = 0.0;
        Vec3 momentA(0.0);
        Vec3 momentB(0.0);
        for (int k = 0; k < m.pointCount; ++k) {
            total = total + impulse[k];
            momentA = momentA + impulse[k] * m.points[k].angularA;
            momentB = momentB + impulse[k] * m.points[k].angularB;
        }
        vA -= (a.invMass * total) * m.normal;
        wA -= a.invInertia * momentA;
        vB += (b.invMass * total) * m.normal;
        wB += b.invInertia * momentB;
    }

    /// The normal velocity at a point from its angular rows (12.4): n . (vB - vA) + (rB x n) . wB
    /// - (rA x n) . wA.
    [[nodiscard]] Real normalVelocity(const Vec3& normal, const SoftPoint& p) const
    {
        return glm::dot(normal, vB - vA) + glm::dot(p.angularB, wB) - glm::dot(p.angularA, wA);
    }

    /// The normal impulse lambda n at a point: its images under the inverse inertias are
    /// lambda IA^-1 (rA x n) and lambda IB^-1 (rB x n).
    void applyNormal(const Vec3& normal, const SoftPoint& p, Real impulse)
    {
        vA -= (a.invMass * impulse) * normal;
        wA -= impulse * p.responseA;
        vB += (b.invMass * impulse) * normal;
        wB += impulse * p.responseB;
    }

    /// The twist impulse tau n on B, -tau n on A.
    void applyTwist(const SoftManifold& m, Real twist)
    {
        wA -= twist * m.twistResponseA;
        wB += twist * m.twistResponseB;
    }

    /// Writes the velocities back; the static body (no inverse mass) never changes, and
    /// manifolds of one colour on different threads share it.
    void store()
    {
        if (a.invMass > 0.0) {
            a.linearVelocity = vA;
            a.angularVelocity = wA;
        }
        if (b.invMass > 0.0) {
            b.linearVelocity = vB;
            b.angularVelocity = wB;
        }
    }
};

/// What (12.3) needs of how a manifold's bodies moved since the step began: n . (dpB - dpA), and
/// the normal turned back by each rotation, dR^T n, so that n . (dR r) = (dR^T n) . r.
struct SoftMotion {
    Real centres = 0.0;
    Vec3 normalA{0.0};
    Vec3 normalB{0.0};

    SoftMotion(const SoftManifold& m, const SoftBody& a, const SoftBody& b)
        : centres(glm::dot(m.normal, b.deltaPosition - a.deltaPosition)),
          normalA(m.normal * a.deltaRotation), normalB(m.normal * b.deltaRotation)
    {
    }
};

} // namespace tumble
