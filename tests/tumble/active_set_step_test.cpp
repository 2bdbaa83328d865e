// The step on the active rows of an island's solve (docs/physics/11-island-solver.md, (11.5e)).
#include "dynamics/active_set_step.hpp"

#include "dynamics/island_solver.hpp"
#include "dynamics/point_impulses.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace tumble {
namespace {

constexpr Real kGravity = 9.81;
constexpr Real kTau = 1.0 / 60.0;

/// A column of `count` unit cubes of mass 1 on the static body (index `count`), each face on the
/// next by its four corners, every body falling at g tau (gravity's push over a sub-step), each
/// point holding `start` of normal impulse already applied (a warm start), friction mu.
struct Column {
    std::vector<SolverBody> bodies;
    std::vector<ContactConstraint> constraints;

    Column(std::uint32_t count, Real start, Real mu)
    {
        for (std::uint32_t i = 0; i < count; ++i) {
            SolverBody& body = bodies.emplace_back();
            body.linearVelocity = Vec3(0.0, -kGravity * kTau, 0.0);
            body.invMass = 1.0;
            // a unit cube of mass 1: I = m (1 + 1) / 12 = 1/6 about every axis
            body.invInertiaWorld = Mat3(6.0);
        }
        bodies.emplace_back(); // the static geometry
        for (std::uint32_t i = 0; i < count; ++i) {
            const std::uint32_t below = i == 0 ? count : i - 1;
            for (const Real x : {-0.5, 0.5}) {
                for (const Real z : {-0.5, 0.5}) {
                    ContactConstraint& c = constraints.emplace_back();
                    c.bodyA = below;
                    c.bodyB = i;
                    c.normal = Vec3(0.0, 1.0, 0.0);
                    c.offsetA = Vec3(x, 0.5, z);
                    c.offsetB = Vec3(x, -0.5, z);
                    c.kineticFriction = mu;
                    c.staticFriction = mu;
                    prepareConstraint(c, bodies, {ConstraintTarget::Substep, kTau, 1e-4, 0.05});
                    c.normalImpulse = start;
                }
            }
        }
        warmStart(constraints, bodies);
    }

    /// The normal impulse through the face under cube i.
    [[nodiscard]] Real load(std::size_t i) const
    {
        Real sum = 0.0;
        for (std::size_t k = 4 * i; k < 4 * i + 4; ++k) {
            sum += constraints[k].normalImpulse;
        }
        return sum;
    }

    [[nodiscard]] Real fastest() const
    {
        Real fastest = 0.0;
        for (const SolverBody& body : bodies) {
            fastest = std::max({fastest, glm::length(body.linearVelocity),
                                glm::length(body.angularVelocity)});
        }
        return fastest;
    }
};

// Statics of a column: the face under cube i carries the weight of it and of the cubes above it,
// so over a sub-step its normal impulse is (n - i) m g tau, and every cube stops. Sweeps pass
// the weight down one cube at a time; the step on the active rows carries it in one go, to
// within its regularisation: delta = 1e-9 of K's diagonal moves the solution by about delta
// times K's condition number, some hundreds for a column of 20.
TEST(ActiveSetStep, CarriesAColumnsWeightDownInOneStep)
{
    const std::uint32_t count = 20;
    Column column(count, 1e-6, 0.5);
    int budget = 256;
    ASSERT_TRUE(stepOnActiveSet(column.constraints, column.bodies, 256, budget));
    EXPECT_GT(budget, 0);
    EXPECT_LT(column.fastest(), 1e-6 * kGravity * kTau);
    for (std::size_t i = 0; i < count; ++i) {
        const Real weight = static_cast<Real>(count - i) * kGravity * kTau;
        EXPECT_NEAR(column.load(i), weight, 1e-6 * weight) << "under cube " << i;
    }
}

// The same column solved by the island's solve, which takes a step on the active rows every
// few sweeps: sweeps alone leave its top falling after 256 (each passes the weight one cube
// further down, and the column's slowest mode converges by about 1 - 1/n^2 a sweep).
TEST(ActiveSetStep, LetsASolveOfAColumnConverge)
{
    const std::uint32_t count = 20;
    Column column(count, 1e-6, 0.5);
    const int sweeps = solveConstraints(column.constraints, column.bodies, 256, 1e-12,
                                        1e-10 * kGravity * kTau);
    EXPECT_LT(sweeps, 64);
    EXPECT_LT(column.fastest(), 1e-8 * kGravity * kTau);
    EXPECT_NEAR(column.load(0), count * kGravity * kTau, 1e-8 * count * kGravity * kTau);
}

/// The kinetic energy of solver bodies (the static one has none).
Real kineticEnergy(const std::vector<SolverBody>& bodies)
{
    Real energy = 0.0;
    for (const SolverBody& body : bodies) {
        if (isFixed(body)) {
            continue;
        }
        const Mat3 inertia = glm::inverse(body.invInertiaWorld);
        energy += 0.5 * glm::dot(body.linearVelocity, body.linearVelocity) / body.invMass +
                  0.5 * glm::dot(body.angularVelocity, inertia * body.angularVelocity);
    }
    return energy;
}

// (8.2) for impulses changed together: the work the step books on its points is the kinetic
// energy it gives the bodies, and with every target 0 (points in contact) a kept step never adds
// kinetic energy; a step not kept leaves bodies and impulses as they were, bit for bit. Random
// columns of assorted friction, some points sliding on the cone's edge.
TEST(ActiveSetStep, BooksItsWorkAndNeverAddsKineticEnergyWhenTheTargetsAreZero)
{
    std::mt19937_64 random(16);
    std::uniform_real_distribution<Real> unit(0.0, 1.0);
    int kept = 0;
    for (int draw = 0; draw < 40; ++draw) {
        Column column(2 + static_cast<std::uint32_t>(draw % 7), 0.2 * unit(random),
                      draw % 5 == 0 ? 0.0 : 0.05 + unit(random));
        for (SolverBody& body : column.bodies) {
            if (!isFixed(body)) {
                body.linearVelocity += Vec3(unit(random) - 0.5, 0.0, unit(random) - 0.5);
                body.angularVelocity = Vec3(unit(random) - 0.5, unit(random) - 0.5, 0.0);
            }
        }
        // a few sweeps find the active rows; some points slide
        solveConstraints(column.constraints, column.bodies, 3, 0.0);
        const std::vector<SolverBody> before = column.bodies;
        const std::vector<ContactConstraint> constraintsBefore = column.constraints;
        Real workBefore = 0.0;
        for (const ContactConstraint& c : column.constraints) {
            workBefore += c.normalWork + c.frictionWork;
        }
        const Real energyBefore = kineticEnergy(column.bodies);
        int budget = 64;
        if (stepOnActiveSet(column.constraints, column.bodies, 64, budget)) {
            ++kept;
            Real work = -workBefore;
            for (const ContactConstraint& c : column.constraints) {
                work += c.normalWork + c.frictionWork;
            }
            const Real energy = kineticEnergy(column.bodies);
            EXPECT_NEAR(work, energy - energyBefore, 1e-12 * (1.0 + energyBefore))
                << "draw " << draw;
            EXPECT_LE(energy, energyBefore * (1.0 + 1e-14)) << "draw " << draw;
            continue;
        }
        for (std::size_t i = 0; i < before.size(); ++i) {
            EXPECT_EQ(column.bodies[i].linearVelocity, before[i].linearVelocity);
            EXPECT_EQ(column.bodies[i].angularVelocity, before[i].angularVelocity);
        }
        for (std::size_t k = 0; k < constraintsBefore.size(); ++k) {
            EXPECT_EQ(column.constraints[k].normalImpulse, constraintsBefore[k].normalImpulse);
            EXPECT_EQ(column.constraints[k].tangentImpulse1,
                      constraintsBefore[k].tangentImpulse1);
        }
    }
    // both outcomes are met: steps kept, and steps whose projection onto the cones undoes them
    EXPECT_GT(kept, 5);
    EXPECT_LT(kept, 35);
}

} // namespace
} // namespace tumble
