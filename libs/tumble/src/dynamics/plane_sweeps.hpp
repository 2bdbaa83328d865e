// The sweeps of a solve at the touching vertices of one cuboid on the ground: preparing a point
// and Gauss-Seidel with friction on the cone (docs/physics/05-normal-impulse.md, 06-friction.md).
#pragma once

#include "dynamics/solver_point.hpp"
#include "tumble/body.hpp"

#include <span>

namespace tumble {

/// Writes every field of `point` for the vertex at offset r: effective masses (5.2), (6.3), the
/// restitution target (5.3) and the friction coefficient (6.2); impulses zero.
void preparePoint(SolverPoint& point, const Body& body, const SolverFrame& frame, const Vec3& r,
                  Real restitution, Real restitutionThreshold);

/// Gauss-Seidel over the points, friction then normal at each, to `convergence` or
/// `iterations` sweeps; (5.4), (5.11), (5.13)-(5.15).
void solvePoints(Body& body, const SolverFrame& frame, std::span<SolverPoint> points,
                 Real targetScale, int iterations, Real convergence, bool accelerate);

} // namespace tumble
