// A soft manifold's sweep in its points' normal velocities (docs/physics/12-soft-step.md,
// (12.4a)) is the Gauss-Seidel sweep that moves the bodies after every point.
#include "dynamics/soft_contact_solver.hpp"
#include "support/random_bodies.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace tumble {
namespace {

/// The relax pass of (12.4) over one frictionless manifold's points forth and back, each point's
/// impulse applied to the bodies at once through its rows (11.2), as in (12.2) with massScale 1.
void sweepMovingTheBodies(SoftManifold& m, std::vector<SoftBody>& bodies, Real inverseSubstep)
{
    SoftBody& a = bodies[m.bodyA];
    SoftBody& b = bodies[m.bodyB];
    const auto visit = [&](SoftPoint& p) {
        const Real u = glm::dot(m.normal, b.linearVelocity - a.linearVelocity) +
                       glm::dot(p.angularB, b.angularVelocity) -
                       glm::dot(p.angularA, a.angularVelocity);
        // (12.3) with the bodies where the step began: s = n . (rB - rA) + base
        const Real gap =
            glm::dot(m.normal, p.anchorB) - glm::dot(m.normal, p.anchorA) + p.baseSeparation;
        const Real bias = gap > 0.0 ? gap * inverseSubstep : 0.0;
        const Real accumulated = std::max(p.normalImpulse - p.normalMass * (u + bias), 0.0);
        const Real applied = accumulated - p.normalImpulse;
        p.normalImpulse = accumulated;
        a.linearVelocity -= a.invMass * applied * m.normal;
        a.angularVelocity -= applied * p.responseA;
        b.linearVelocity += b.invMass * applied * m.normal;
        b.angularVelocity += applied * p.responseB;
    };
    for (int k = 0; k < m.pointCount; ++k) {
        visit(m.points[k]);
    }
    for (int k = m.pointCount - 1; k >= 0; --k) {
        visit(m.points[k]);
    }
}

TEST(SoftSweep, TrackedNormalVelocitiesGiveTheSweepThatMovesTheBodies)
{
    const Real h = 1.0 / 240.0;
    const SoftSolveSettings settings{makeSoftness(30.0, 10.0, h), makeSoftness(60.0, 5.0, h),
                                     1.0 / h, 3.0};
    for (std::uint32_t seed = 1; seed <= 20; ++seed) {
        std::mt19937_64 random(seed);
        std::vector<SoftBody> bodies(2);
        for (SoftBody& body : bodies) {
            body.linearVelocity = testing::randomVector(random);
            body.angularVelocity = testing::randomVector(random);
            body.invMass = testing::randomInverseMass(random);
            body.invInertia = testing::randomInverseInertia(random);
        }
        SoftManifold m;
        m.bodyA = 0;
        m.bodyB = 1;
        m.normal = glm::normalize(testing::randomVector(random) + Vec3(0.0, 2.0, 0.0));
        orthonormalBasis(m.normal, m.tangent1, m.tangent2);
        m.friction = 0.0;
        m.pointCount = 2 + static_cast<int>(seed % 3);
        for (int k = 0; k < m.pointCount; ++k) {
            SoftPoint& p = m.points[k];
            p.anchorA = testing::randomVector(random);
            p.anchorB = testing::randomVector(random);
            // the gap s = n . (rB - rA) + base: touching, and at point 1 a speculative gap
            const Real gap = (k == 1 ? 0.01 : -0.01) * (0.5 + 0.5 * testing::randomUnit(random));
            p.baseSeparation = gap - glm::dot(m.normal, p.anchorB - p.anchorA);
            p.normalImpulse = 0.5 + 0.5 * testing::randomUnit(random);
        }
        prepareSoftRows(m, bodies);
        SoftManifold reference = m;
        std::vector<SoftBody> expected = bodies;
        sweepMovingTheBodies(reference, expected, settings.inverseSubstep);
        std::vector<SoftManifold> manifolds{m};
        solveSoft(manifolds, bodies, settings, false, SoftColours{}, 1, nullptr);
        for (int k = 0; k < m.pointCount; ++k) {
            EXPECT_NEAR(manifolds[0].points[k].normalImpulse, reference.points[k].normalImpulse,
                        1e-12)
                << "seed " << seed << " point " << k;
        }
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            for (int axis = 0; axis < 3; ++axis) {
                EXPECT_NEAR(bodies[i].linearVelocity[axis], expected[i].linearVelocity[axis], 1e-12);
                EXPECT_NEAR(bodies[i].angularVelocity[axis], expected[i].angularVelocity[axis],
                            1e-12);
            }
        }
    }
}

} // namespace
} // namespace tumble
