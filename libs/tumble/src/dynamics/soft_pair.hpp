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

    /// The velocity of B relative to A at the manifold's centre, (vB + wB x cB) - (vA + wA x cA):
    /// its components along t1 and t2 are the friction rows' slips, t_i . (vB - vA) + (cB x t_i)
    /// . wB - (cA x t_i) . wA (11.1), as (c x t) . w = t . (w x c) (12.5a).
    [[nodiscard]] Vec3 centreVelocity(const SoftManifold& m) const
    {
        return (vB + glm::cross(wB, m.centreB)) - (vA + glm::cross(wA, m.centreA));
    }

    /// The friction impulse P = d1 t1 + d2 t2 at the centre: its moments are c x P (12.5a).
    void applyFriction(const SoftManifold& m, Real d1, Real d2)
    {
        const Vec3 impulse = d1 * m.tangent1 + d2 * m.tangent2;
        vA -= a.invMass * impulse;
        wA -= a.invInertia * glm::cross(m.centreA, impulse);
        vB += b.invMass * impulse;
        wB += b.invInertia * glm::cross(m.centreB, impulse);
    }

    /// The sum of a manifold's points' impulses, sum_k lambda_k, and of their levers on each
    /// side, sum_k lambda_k r_k (12.4b).
    struct Levers {
        Real total = 0.0;
        Vec3 a{0.0};
        Vec3 b{0.0};
    };

    static Levers leversOf(const SoftManifold& m, const std::array<Real, 4>& impulse)
    {
        Levers sums;
        for (int k = 0; k < m.pointCount; ++k) {
            sums.total = sums.total + impulse[k];
            sums.a = sums.a + impulse[k] * m.points[k].anchorA;
            sums.b = sums.b + impulse[k] * m.points[k].anchorB;
        }
        return sums;
    }

    /// The normal impulses of a manifold's points at once: their sum along n, and their moments
    /// sum_k lambda_k (r_k x n) = (sum_k lambda_k r_k) x n through each inverse inertia (12.4b).
    void applyNormals(const SoftManifold& m, const std::array<Real, 4>& impulse)
    {
        const Levers sums = leversOf(m, impulse);
        vA -= (a.invMass * sums.total) * m.normal;
        wA -= a.invInertia * glm::cross(sums.a, m.normal);
        vB += (b.invMass * sums.total) * m.normal;
        wB += b.invInertia * glm::cross(sums.b, m.normal);
    }

    /// A manifold's accumulated impulses at once (the warm start, (12.5)): the normal ones, the
    /// twist tau n and the friction P, one linear impulse and one moment a body (12.4b), (12.5a).
    void applyAccumulated(const SoftManifold& m, const std::array<Real, 4>& impulse, Real twist,
                          Real f1, Real f2)
    {
        const Levers sums = leversOf(m, impulse);
        const Vec3 friction = f1 * m.tangent1 + f2 * m.tangent2;
        const Vec3 linear = sums.total * m.normal + friction;
        const Vec3 twistMoment = twist * m.normal;
        vA -= a.invMass * linear;
        wA -= a.invInertia * (glm::cross(sums.a, m.normal) + glm::cross(m.centreA, friction) +
                              twistMoment);
        vB += b.invMass * linear;
        wB += b.invInertia * (glm::cross(sums.b, m.normal) + glm::cross(m.centreB, friction) +
                              twistMoment);
    }

    /// The normal velocities of a manifold's points (12.4b): n . (vB - vA) + (rB x n) . wB -
    /// (rA x n) . wA = n . (vB - vA) + rB . (n x wB) - rA . (n x wA), the first term and the
    /// two turns formed once for the manifold.
    [[nodiscard]] std::array<Real, 4> normalVelocities(const SoftManifold& m) const
    {
        const Real along = glm::dot(m.normal, vB - vA);
        const Vec3 turnA = glm::cross(m.normal, wA);
        const Vec3 turnB = glm::cross(m.normal, wB);
        std::array<Real, 4> u{};
        for (int k = 0; k < m.pointCount; ++k) {
            u[k] = along + glm::dot(m.points[k].anchorB, turnB) -
                   glm::dot(m.points[k].anchorA, turnA);
        }
        return u;
    }

    /// The velocities of the manifold's rows (12.8): the points' normal velocities, the spin
    /// about the normal, and the sliding at the centre along the two tangents.
    struct RowVelocities {
        std::array<Real, 4> normal;
        Real spin, slip1, slip2;
    };
    [[nodiscard]] RowVelocities rowVelocities(const SoftManifold& m) const
    {
        const Vec3 sliding = centreVelocity(m);
        return {normalVelocities(m), glm::dot(m.normal, wB - wA), glm::dot(m.tangent1, sliding),
                glm::dot(m.tangent2, sliding)};
    }

    /// The normal velocity at a point from its angular rows (restitution, (12.6)): n . (vB - vA)
    /// + (rB x n) . wB - (rA x n) . wA.
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
