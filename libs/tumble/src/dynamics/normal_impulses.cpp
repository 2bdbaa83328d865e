// The normal contact problem of one body solved exactly, by its active set.
#include "dynamics/normal_impulses.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble {

namespace {

/// A set of at most three points whose matrix A_SS is this close to singular relative to its
/// diagonal (det / prod A_ii, which is 1 for independent points and 0 for dependent ones) is
/// skipped: a smaller set gives the same velocities.
constexpr Real kDependentPoints = 1e-12;

struct Candidate {
    std::array<int, 3> points{};
    int count = 0;
};

/// Every set of at most three of the n points.
std::array<Candidate, 93> candidateSets(int n, int& total)
{
    std::array<Candidate, 93> sets{};
    total = 0;
    sets[total++] = Candidate{};
    for (int i = 0; i < n; ++i) {
        sets[total++] = Candidate{{i, 0, 0}, 1};
        for (int j = i + 1; j < n; ++j) {
            sets[total++] = Candidate{{i, j, 0}, 2};
            for (int k = j + 1; k < n; ++k) {
                sets[total++] = Candidate{{i, j, k}, 3};
            }
        }
    }
    return sets;
}

} // namespace

std::array<Real, 8> solveNormalImpulses(Real invMass, const Mat3& invInertia, const Vec3& normal,
                                        std::span<const Vec3> offsets,
                                        std::span<const Real> freeVelocities)
{
    const int n = static_cast<int>(offsets.size());
    // (5.11): A_ij = 1/m + (r_i x n) . I^-1 (r_j x n), the change of w_i per unit lambda_j.
    std::array<Vec3, 8> angular{};
    for (int i = 0; i < n; ++i) {
        angular[i] = glm::cross(offsets[i], normal);
    }
    std::array<std::array<Real, 8>, 8> a{};
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            a[i][j] = invMass + glm::dot(angular[i], invInertia * angular[j]);
        }
    }
    // A has rank at most 3 (the impulses move only v . n and the two tilts), so some solution
    // pushes at most three independent points: try every such set, solve A_SS lambda_S = -b_S,
    // and keep the one that violates lambda >= 0 and w >= 0 least, in velocity units (zero, up
    // to rounding, for the solution).
    int total = 0;
    const std::array<Candidate, 93> sets = candidateSets(n, total);
    std::array<Real, 8> best{};
    Real bestViolation = std::numeric_limits<Real>::infinity();
    for (int s = 0; s < total; ++s) {
        const Candidate& set = sets[s];
        Mat3 system(1.0);
        Vec3 rhs(0.0);
        Real diagonalProduct = 1.0;
        for (int p = 0; p < set.count; ++p) {
            for (int q = 0; q < set.count; ++q) {
                system[q][p] = a[set.points[p]][set.points[q]]; // glm: [column][row]
            }
            rhs[p] = -freeVelocities[set.points[p]];
            diagonalProduct *= a[set.points[p]][set.points[p]];
        }
        const Real determinant = glm::determinant(system);
        if (!(determinant > kDependentPoints * diagonalProduct)) {
            continue;
        }
        const Vec3 solved = glm::inverse(system) * rhs;
        std::array<Real, 8> lambda{};
        Real violation = 0.0;
        for (int p = 0; p < set.count; ++p) {
            lambda[set.points[p]] = solved[p];
            violation = std::max(violation, -solved[p] * a[set.points[p]][set.points[p]]);
        }
        for (int i = 0; i < n; ++i) {
            Real w = freeVelocities[i];
            for (int j = 0; j < n; ++j) {
                w += a[i][j] * lambda[j];
            }
            violation = std::max(violation, -w);
        }
        if (violation < bestViolation) {
            bestViolation = violation;
            best = lambda;
        }
    }
    for (Real& lambda : best) {
        lambda = std::max(0.0, lambda);
    }
    return best;
}

} // namespace tumble
