// A soft manifold's sweep in its points' normal velocities and levers, and its friction through
// its centres (docs/physics/12-soft-step.md, (12.4a), (12.4b), (12.5a)), are the Gauss-Seidel
// rows of (11.1)-(11.3) that move the bodies through each row's angular parts and images.
#include "dynamics/soft_contact_solver.hpp"
#include "support/random_bodies.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace tumble {
namespace {

/// The friction rows' angular parts at the centre, c x t_i (11.1).
struct CentreRows {
    Vec3 a1, a2, b1, b2;
};

CentreRows centreRowsOf(const SoftManifold& m)
{
    return {glm::cross(m.centreA, m.tangent1), glm::cross(m.centreA, m.tangent2),
            glm::cross(m.centreB, m.tangent1), glm::cross(m.centreB, m.tangent2)};
}

/// A friction impulse (d1, d2) applied through its rows' images IA^-1 (cA x t_i).
void applyFrictionRows(const SoftManifold& m, SoftBody& a, SoftBody& b, Real d1, Real d2)
{
    const CentreRows rows = centreRowsOf(m);
    a.linearVelocity -= a.invMass * (d1 * m.tangent1 + d2 * m.tangent2);
    a.angularVelocity -= a.invInertia * rows.a1 * d1 + a.invInertia * rows.a2 * d2;
    b.linearVelocity += b.invMass * (d1 * m.tangent1 + d2 * m.tangent2);
    b.angularVelocity += b.invInertia * rows.b1 * d1 + b.invInertia * rows.b2 * d2;
}

/// The relax pass of (12.4) over one manifold's points forth and back, each point's impulse
/// applied to the bodies at once through its rows (11.2), as in (12.2) with massScale 1; then
/// the twist and the friction disc of (12.5), their slips read through the rows c x t_i.
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
    Real load = 0.0;
    Real twistLimit = 0.0;
    for (int k = 0; k < m.pointCount; ++k) {
        load += m.points[k].normalImpulse;
        twistLimit += m.points[k].leverArm * m.points[k].normalImpulse;
    }
    twistLimit *= m.friction;
    const Real spin = glm::dot(m.normal, b.angularVelocity - a.angularVelocity);
    const Real twist = std::clamp(m.twistImpulse - m.twistMass * spin, -twistLimit, twistLimit);
    a.angularVelocity -= (twist - m.twistImpulse) * (a.invInertia * m.normal);
    b.angularVelocity += (twist - m.twistImpulse) * (b.invInertia * m.normal);
    m.twistImpulse = twist;
    const CentreRows rows = centreRowsOf(m);
    const Vec3 relative = b.linearVelocity - a.linearVelocity;
    const Real slip1 = glm::dot(m.tangent1, relative) + glm::dot(rows.b1, b.angularVelocity) -
                       glm::dot(rows.a1, a.angularVelocity);
    const Real slip2 = glm::dot(m.tangent2, relative) + glm::dot(rows.b2, b.angularVelocity) -
                       glm::dot(rows.a2, a.angularVelocity);
    Real next1 = m.frictionImpulse1 - (m.tangentMass[0] * slip1 + m.tangentMass[1] * slip2);
    Real next2 = m.frictionImpulse2 - (m.tangentMass[1] * slip1 + m.tangentMass[2] * slip2);
    const Real size = std::hypot(next1, next2);
    if (size > m.friction * load) {
        next1 *= m.friction * load / size;
        next2 *= m.friction * load / size;
    }
    applyFrictionRows(m, a, b, next1 - m.frictionImpulse1, next2 - m.frictionImpulse2);
    m.frictionImpulse1 = next1;
    m.frictionImpulse2 = next2;
}

/// Two bodies of random velocities and mass properties, and a manifold between them of two to
/// four points with random anchors, touching but at point 1, with accumulated impulses.
struct RandomContact {
    std::vector<SoftBody> bodies;
    SoftManifold manifold;
};

/// The bodies' kinetic energy, 1/2 m v.v + 1/2 w.(I w), from their inverse mass and inertia.
Real kineticEnergyOf(const std::vector<SoftBody>& bodies)
{
    Real energy = 0.0;
    for (const SoftBody& body : bodies) {
        energy += 0.5 * glm::dot(body.linearVelocity, body.linearVelocity) / body.invMass +
                  0.5 * glm::dot(body.angularVelocity,
                                 glm::inverse(body.invInertia) * body.angularVelocity);
    }
    return energy;
}

RandomContact randomContact(std::uint32_t seed)
{
    std::mt19937_64 random(seed);
    RandomContact contact;
    contact.bodies.resize(2);
    for (SoftBody& body : contact.bodies) {
        body.linearVelocity = testing::randomVector(random);
        body.angularVelocity = testing::randomVector(random);
        body.invMass = testing::randomInverseMass(random);
        body.invInertia = testing::randomInverseInertia(random);
    }
    SoftManifold& m = contact.manifold;
    m.bodyA = 0;
    m.bodyB = 1;
    m.normal = glm::normalize(testing::randomVector(random) + Vec3(0.0, 2.0, 0.0));
    orthonormalBasis(m.normal, m.tangent1, m.tangent2);
    m.friction = 0.2 + 0.6 * testing::randomUnit(random);
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
    m.frictionImpulse1 = 0.1 * testing::randomUnit(random);
    m.frictionImpulse2 = -0.1 * testing::randomUnit(random);
    m.twistImpulse = 0.05 * testing::randomUnit(random);
    prepareSoftRows(m, contact.bodies);
    return contact;
}

void expectSameVelocities(const std::vector<SoftBody>& bodies,
                          const std::vector<SoftBody>& expected, std::uint32_t seed)
{
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_NEAR(bodies[i].linearVelocity[axis], expected[i].linearVelocity[axis], 1e-12)
                << "seed " << seed << " body " << i;
            EXPECT_NEAR(bodies[i].angularVelocity[axis], expected[i].angularVelocity[axis], 1e-12)
                << "seed " << seed << " body " << i;
        }
    }
}

TEST(SoftSweep, APassInVelocitiesLeversAndCentresIsThePassThroughTheRows)
{
    const Real h = 1.0 / 240.0;
    const SoftSolveSettings settings{makeSoftness(30.0, 10.0, h), makeSoftness(60.0, 5.0, h),
                                     1.0 / h, 3.0};
    for (std::uint32_t seed = 1; seed <= 20; ++seed) {
        RandomContact contact = randomContact(seed);
        const SoftManifold& m = contact.manifold;
        SoftManifold reference = m;
        std::vector<SoftBody> expected = contact.bodies;
        sweepMovingTheBodies(reference, expected, settings.inverseSubstep);
        std::vector<SoftManifold> manifolds{m};
        solveSoft(manifolds, contact.bodies, settings, false, SoftColours{}, 1, nullptr);
        for (int k = 0; k < m.pointCount; ++k) {
            EXPECT_NEAR(manifolds[0].points[k].normalImpulse, reference.points[k].normalImpulse,
                        1e-12)
                << "seed " << seed << " point " << k;
        }
        EXPECT_NEAR(manifolds[0].twistImpulse, reference.twistImpulse, 1e-12) << "seed " << seed;
        EXPECT_NEAR(manifolds[0].frictionImpulse1, reference.frictionImpulse1, 1e-12);
        EXPECT_NEAR(manifolds[0].frictionImpulse2, reference.frictionImpulse2, 1e-12);
        expectSameVelocities(contact.bodies, expected, seed);
    }
}

// (12.4b), (12.5a): the warm start's one impulse and one moment a body are the manifold's rows
// applied one by one through their images, lambda_k IA^-1 (rA_k x n), tau IA^-1 n and
// IA^-1 (cA x t_i) lambda_ti.
TEST(SoftSweep, TheWarmStartIsEveryRowAppliedThroughItsImages)
{
    for (std::uint32_t seed = 1; seed <= 20; ++seed) {
        RandomContact contact = randomContact(seed);
        const SoftManifold& m = contact.manifold;
        std::vector<SoftBody> expected = contact.bodies;
        SoftBody& a = expected[0];
        SoftBody& b = expected[1];
        for (int k = 0; k < m.pointCount; ++k) {
            const SoftPoint& p = m.points[k];
            a.linearVelocity -= a.invMass * p.normalImpulse * m.normal;
            a.angularVelocity -= p.normalImpulse * p.responseA;
            b.linearVelocity += b.invMass * p.normalImpulse * m.normal;
            b.angularVelocity += p.normalImpulse * p.responseB;
        }
        a.angularVelocity -= m.twistImpulse * (a.invInertia * m.normal);
        b.angularVelocity += m.twistImpulse * (b.invInertia * m.normal);
        applyFrictionRows(m, a, b, m.frictionImpulse1, m.frictionImpulse2);
        std::vector<SoftManifold> manifolds{m};
        const Real kineticBefore = kineticEnergyOf(contact.bodies);
        warmStartSoft(manifolds, contact.bodies, SoftColours{}, 1, nullptr);
        expectSameVelocities(contact.bodies, expected, seed);
        // (12.8): the work booked for the impulses applied at once is the kinetic change
        Real work = manifolds[0].frictionWork - m.frictionWork;
        for (int k = 0; k < m.pointCount; ++k) {
            work += manifolds[0].points[k].normalWork - m.points[k].normalWork;
        }
        const Real change = kineticEnergyOf(contact.bodies) - kineticBefore;
        EXPECT_NEAR(work, change, 1e-10 * (1.0 + kineticBefore)) << seed;
    }
}

} // namespace
} // namespace tumble
