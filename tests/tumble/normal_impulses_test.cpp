// The normal contact problem solved exactly (docs/physics/05-normal-impulse.md, (5.11)).
#include "dynamics/normal_impulses.hpp"

#include "tumble/shape.hpp"

#include <gtest/gtest.h>

#include <array>
#include <random>

namespace tumble {
namespace {

struct Problem {
    Real invMass = 1.0;
    Mat3 invInertia{1.0};
    std::array<Vec3, 4> offsets{};
    std::array<Real, 4> freeVelocities{};
};

/// w_i = b_i + sum_j A_ij lambda_j, A as in (5.11).
std::array<Real, 4> normalVelocities(const Problem& problem, const std::array<Real, 8>& impulses)
{
    const Vec3 n(0.0, 1.0, 0.0);
    std::array<Real, 4> w = problem.freeVelocities;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            const Vec3 ri = glm::cross(problem.offsets[i], n);
            const Vec3 rj = glm::cross(problem.offsets[j], n);
            w[i] += (problem.invMass + glm::dot(ri, problem.invInertia * rj)) * impulses[j];
        }
    }
    return w;
}

/// The bottom corners of a box with these full extents, centre at the origin.
Problem box(const Vec3& size, Real mass)
{
    Problem problem;
    problem.invMass = 1.0 / mass;
    problem.invInertia = Mat3(1.0 / cuboidInertiaDiagonal(mass, size).x, 0.0, 0.0, 0.0,
                              1.0 / cuboidInertiaDiagonal(mass, size).y, 0.0, 0.0, 0.0,
                              1.0 / cuboidInertiaDiagonal(mass, size).z);
    const Vec3 h = 0.5 * size;
    problem.offsets = {Vec3(-h.x, -h.y, -h.z), Vec3(h.x, -h.y, -h.z), Vec3(-h.x, -h.y, h.z),
                       Vec3(h.x, -h.y, h.z)};
    return problem;
}

std::array<Real, 8> solve(const Problem& problem)
{
    return solveNormalImpulses(problem.invMass, problem.invInertia, Vec3(0.0, 1.0, 0.0),
                               problem.offsets, problem.freeVelocities);
}

TEST(NormalImpulses, AFaceOnTheGroundCarriesExactlyItsWeight)
{
    Problem problem = box(Vec3(2.0, 2.0, 2.0), 3.0);
    problem.freeVelocities.fill(-9.81 / 240.0);
    const std::array<Real, 8> impulses = solve(problem);
    Real total = 0.0;
    for (int i = 0; i < 4; ++i) {
        EXPECT_GE(impulses[i], 0.0);
        total += impulses[i];
    }
    EXPECT_NEAR(total, 3.0 * 9.81 / 240.0, 1e-14);
    for (const Real w : normalVelocities(problem, impulses)) {
        EXPECT_NEAR(w, 0.0, 1e-15);
    }
}

TEST(NormalImpulses, SolvesThePlateOnItsEdgeThatGaussSeidelCouldNot)
{
    // The bottom of a 0.27 x 0.27 x 0.001 plate standing on an edge, with random approach and
    // separation at the corners: the result satisfies (5.11) to rounding.
    std::mt19937_64 random(6);
    std::uniform_real_distribution<Real> speed(-1e-3, 1e-3);
    for (int draw = 0; draw < 200; ++draw) {
        Problem problem = box(Vec3(0.266, 0.266, 0.001), 4944.0);
        for (Real& b : problem.freeVelocities) {
            b = speed(random);
        }
        const std::array<Real, 8> impulses = solve(problem);
        const std::array<Real, 4> w = normalVelocities(problem, impulses);
        for (int i = 0; i < 4; ++i) {
            EXPECT_GE(impulses[i], 0.0);
            EXPECT_GE(w[i], -1e-15);
            // complementarity: a pushed corner leaves at exactly its target (rounding of 1e-3)
            if (impulses[i] > 0.0) {
                EXPECT_NEAR(w[i], 0.0, 1e-15);
            }
        }
    }
}

} // namespace
} // namespace tumble
