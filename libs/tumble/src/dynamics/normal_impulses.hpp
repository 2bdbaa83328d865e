// The normal contact problem of one body solved exactly, by its active set, for when
// Gauss-Seidel does not converge (docs/physics/05-normal-impulse.md, (5.11)).
#pragma once

#include "tumble/math.hpp"

#include <array>
#include <span>

namespace tumble {

/// The normal impulses lambda_i >= 0 at offsets r_i (at most 8) that leave every point with
/// normal velocity w_i = b_i + sum_j A_ij lambda_j >= 0 and lambda_i w_i = 0, where
/// A_ij = 1/m + (r_i x n) . I^-1 (r_j x n) and b_i is the point's normal velocity without any
/// normal impulse minus its target (5.11).
std::array<Real, 8> solveNormalImpulses(Real invMass, const Mat3& invInertia, const Vec3& normal,
                                        std::span<const Vec3> offsets,
                                        std::span<const Real> freeVelocities);

} // namespace tumble
