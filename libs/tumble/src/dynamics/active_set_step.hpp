// A step of the contact impulses over the points the sweeps have found pushing (and sticking)
// at once: conjugate gradients on those rows, projected back onto the cones, kept only where
// it lowers the solve's objective (docs/physics/11-island-solver.md, (11.5e)).
#pragma once

#include "dynamics/contact_constraint.hpp"

#include <span>

namespace tumble {

/// (11.5e): the rows of the points with a positive normal impulse (their normal rows, and their
/// tangent rows where the friction is inside the cone) brought to their targets together by
/// conjugate gradients on K = J M^-1 J^T, at most `iterations` of them, each taken from
/// `budget` (the caller's bound on a solve's work), until the rows' residual is within
/// `velocityTolerance` (m/s) or 1e-12 of its start; the other impulses stay. The result is
/// clamped to lambda_n >= 0 and to the cones, and applied at the first of the scales 1, 1/2,
/// 1/4 and 1/8 that lowers the objective the sweeps lower (the kinetic energy less the targets'
/// work); each point's work is booked (8.2). Returns whether it was applied.
bool stepOnActiveSet(std::span<ContactConstraint> constraints, std::span<SolverBody> bodies,
                     int iterations, int& budget, Real velocityTolerance = 0.0);

} // namespace tumble
