// Random bodies for the tests that compare the lanes with one manifold at a time: inverse masses
// from 1/10 to 1 and inverse inertias of assorted principal moments and axes.
#pragma once

#include "tumble/math.hpp"

#include <random>

namespace tumble::testing {

inline Real randomUnit(std::mt19937_64& random)
{
    return std::uniform_real_distribution<Real>(-1.0, 1.0)(random);
}

inline Vec3 randomVector(std::mt19937_64& random)
{
    return Vec3(randomUnit(random), randomUnit(random), randomUnit(random));
}

inline Real randomInverseMass(std::mt19937_64& random)
{
    return 1.0 / (1.0 + 9.0 * (0.5 + 0.5 * randomUnit(random)));
}

/// R diag(1/I) R^T for principal moments I in [0.5, 1] and a random rotation R.
inline Mat3 randomInverseInertia(std::mt19937_64& random)
{
    const Vec3 inertia = 0.5 + 0.5 * glm::abs(randomVector(random));
    const Quat turn = glm::normalize(Quat(randomUnit(random), randomVector(random)));
    const Mat3 rotation = glm::mat3_cast(turn);
    return rotation *
           Mat3(1.0 / inertia.x, 0.0, 0.0, 0.0, 1.0 / inertia.y, 0.0, 0.0, 0.0, 1.0 / inertia.z) *
           glm::transpose(rotation);
}

} // namespace tumble::testing
