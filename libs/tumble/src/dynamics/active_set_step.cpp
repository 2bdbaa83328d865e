// Conjugate gradients on the rows the sweeps have found active (docs/physics/11-island-solver.md,
// (11.5e)).
#include "dynamics/active_set_step.hpp"

#include "dynamics/friction_cone.hpp"
#include "dynamics/point_impulses.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace tumble {

namespace {

/// Scales of the projected step tried, 1, 1/2, 1/4 and 1/8, before it is refused.
constexpr int kHalvings = 4;

/// A row of J: the direction `axis` (0: n, 1: t1, 2: t2) of constraint `point`.
struct Row {
    std::uint32_t point = 0;
    int axis = 0;
};

/// The relative point velocity along a row of a constraint between two of `bodies`.
Real rowVelocity(const ContactConstraint& c, std::span<const SolverBody> bodies, int axis)
{
    return rowVelocity(c, bodies[c.bodyA], bodies[c.bodyB], axis);
}

/// Where the friction of a pushing point is strictly inside its cone: its tangent rows are
/// equalities (sticking); on the cone the point slides and its friction stays as it is.
bool sticks(const ContactConstraint& c)
{
    const Real bound = c.friction * c.normalImpulse;
    const Real magnitude = std::sqrt(c.tangentImpulse1 * c.tangentImpulse1 +
                                     c.tangentImpulse2 * c.tangentImpulse2);
    return bound > 0.0 && magnitude < (1.0 - 1e-9) * bound;
}

/// The vectors of a step, kept per thread from solve to solve.
struct ActiveSetScratch {
    std::vector<Row> rows;
    std::vector<Real> solution;
    std::vector<Real> residual;
    std::vector<Real> diagonal;
    std::vector<Real> preconditioned;
    std::vector<Real> direction;
    std::vector<Real> product;
    /// Bodies with the island's masses and no velocity, for K's products.
    std::vector<SolverBody> delta;
    /// The bodies before the step, restored when it is not kept.
    std::vector<SolverBody> saved;
    /// Per point: the projected impulses, their change, the row velocities before the change,
    /// and each row's work (8.2).
    std::vector<std::array<Real, 3>> next;
    std::vector<std::array<Real, 3>> change;
    std::vector<std::array<Real, 3>> before;
    std::vector<std::array<Real, 3>> work;
};

/// product = K direction over the rows, K = J M^-1 J^T (11.2): the direction's impulses applied
/// to bodies at rest, then read back along each row.
void multiply(std::span<const ContactConstraint> constraints, ActiveSetScratch& s)
{
    for (SolverBody& body : s.delta) {
        body.linearVelocity = Vec3(0.0);
        body.angularVelocity = Vec3(0.0);
    }
    for (std::size_t r = 0; r < s.rows.size(); ++r) {
        const ContactConstraint& c = constraints[s.rows[r].point];
        const int axis = s.rows[r].axis;
        applyAlong(c, s.delta[c.bodyA], s.delta[c.bodyB], directionOf(c, axis), axis,
                   s.direction[r]);
    }
    for (std::size_t r = 0; r < s.rows.size(); ++r) {
        s.product[r] = rowVelocity(constraints[s.rows[r].point], s.delta, s.rows[r].axis);
    }
}

Real dot(const std::vector<Real>& x, const std::vector<Real>& y)
{
    Real sum = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sum += x[i] * y[i];
    }
    return sum;
}

/// The active rows and their residuals, target less velocity (0 for a tangent row).
void gatherRows(std::span<const ContactConstraint> constraints,
                std::span<const SolverBody> bodies, ActiveSetScratch& s)
{
    s.rows.clear();
    s.residual.clear();
    for (std::size_t k = 0; k < constraints.size(); ++k) {
        const ContactConstraint& c = constraints[k];
        if (!(c.normalImpulse > 0.0)) {
            continue;
        }
        const auto point = static_cast<std::uint32_t>(k);
        s.rows.push_back({point, 0});
        s.residual.push_back(c.targetNormalVelocity - rowVelocity(c, bodies, 0));
        if (sticks(c)) {
            for (int axis = 1; axis <= 2; ++axis) {
                s.rows.push_back({point, axis});
                s.residual.push_back(-rowVelocity(c, bodies, axis));
            }
        }
    }
}

/// The diagonal of K on a row: the inverse of the point's normal mass, or K_t's diagonal.
Real diagonalOf(const ContactConstraint& c, int axis)
{
    return axis == 0 ? 1.0 / c.normalMass : c.tangentK[axis == 1 ? 0 : 3];
}

/// Conjugate gradients for (K + delta D) x = residual from x = 0, preconditioned by D, the
/// diagonal of K (Jacobi). K is only positive semidefinite (a face on a face has twelve rows for
/// six relative motions); delta D keeps the iteration off K's null space, where rounding would
/// otherwise grow. Each iteration lowers x^T (K + delta D) x / 2 - residual^T x, so the last
/// iterate is the best one, even where the residual's norm rises.
void conjugateGradients(std::span<const ContactConstraint> constraints, int iterations,
                        Real velocityTolerance, int& budget, ActiveSetScratch& s)
{
    constexpr Real kRegularisation = 1e-9;
    const std::size_t n = s.rows.size();
    s.diagonal.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        s.diagonal[i] = diagonalOf(constraints[s.rows[i].point], s.rows[i].axis);
    }
    s.solution.assign(n, 0.0);
    s.preconditioned.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        s.preconditioned[i] = s.residual[i] / s.diagonal[i];
    }
    s.direction = s.preconditioned;
    s.product.assign(n, 0.0);
    s.delta.assign(s.saved.begin(), s.saved.end());
    Real rz = dot(s.residual, s.preconditioned);
    Real squared = dot(s.residual, s.residual);
    // |r| <= tolerance bounds every row's residual, a velocity, by the solve's own tolerance
    const Real stop = std::max(1e-24 * squared, velocityTolerance * velocityTolerance);
    for (int iteration = 0; iteration < iterations && budget > 0 && squared > stop;
         ++iteration, --budget) {
        multiply(constraints, s);
        for (std::size_t i = 0; i < n; ++i) {
            s.product[i] += kRegularisation * s.diagonal[i] * s.direction[i];
        }
        const Real curvature = dot(s.direction, s.product);
        if (!(curvature > 0.0)) {
            break;
        }
        const Real alpha = rz / curvature;
        for (std::size_t i = 0; i < n; ++i) {
            s.solution[i] += alpha * s.direction[i];
            s.residual[i] -= alpha * s.product[i];
            s.preconditioned[i] = s.residual[i] / s.diagonal[i];
        }
        squared = dot(s.residual, s.residual);
        const Real next = dot(s.residual, s.preconditioned);
        const Real beta = next / rz;
        rz = next;
        for (std::size_t i = 0; i < n; ++i) {
            s.direction[i] = s.preconditioned[i] + beta * s.direction[i];
        }
    }
}

/// The step's impulses projected, lambda_n >= 0 and friction inside mu lambda_n, their change,
/// and the row velocities before it.
void projectStep(std::span<const ContactConstraint> constraints,
                 std::span<const SolverBody> bodies, ActiveSetScratch& s)
{
    s.change.assign(constraints.size(), {0.0, 0.0, 0.0});
    for (std::size_t r = 0; r < s.rows.size(); ++r) {
        s.change[s.rows[r].point][static_cast<std::size_t>(s.rows[r].axis)] = s.solution[r];
    }
    s.next.resize(constraints.size());
    s.before.resize(constraints.size());
    for (std::size_t k = 0; k < constraints.size(); ++k) {
        const ContactConstraint& c = constraints[k];
        const Real normal = std::max(0.0, c.normalImpulse + s.change[k][0]);
        const FrictionImpulse friction =
            scaledIntoDisc(c.tangentImpulse1 + s.change[k][1],
                           c.tangentImpulse2 + s.change[k][2], c.friction * normal);
        s.next[k] = {normal, friction.impulse1, friction.impulse2};
        s.change[k] = {normal - c.normalImpulse, friction.impulse1 - c.tangentImpulse1,
                       friction.impulse2 - c.tangentImpulse2};
        for (int axis = 0; axis < 3; ++axis) {
            s.before[k][static_cast<std::size_t>(axis)] = rowVelocity(c, bodies, axis);
        }
    }
}

/// Applies the projected change to the bodies and returns its change of the objective: (8.2)
/// holds for impulses changed together, the kinetic energy changing by the sum over the rows of
/// dlambda (u_before + u_after) / 2, u the row velocities before and after the whole change;
/// the targets' work, target_n dlambda_n, comes off.
Real applyStep(std::span<const ContactConstraint> constraints, std::span<SolverBody> bodies,
               ActiveSetScratch& s)
{
    for (std::size_t k = 0; k < constraints.size(); ++k) {
        const ContactConstraint& c = constraints[k];
        for (int axis = 0; axis < 3; ++axis) {
            applyAlong(c, bodies[c.bodyA], bodies[c.bodyB], directionOf(c, axis), axis,
                       s.change[k][static_cast<std::size_t>(axis)]);
        }
    }
    Real objective = 0.0;
    s.work.resize(constraints.size());
    for (std::size_t k = 0; k < constraints.size(); ++k) {
        const ContactConstraint& c = constraints[k];
        for (int axis = 0; axis < 3; ++axis) {
            const auto a = static_cast<std::size_t>(axis);
            s.work[k][a] =
                s.change[k][a] * 0.5 * (s.before[k][a] + rowVelocity(c, bodies, axis));
            objective += s.work[k][a];
        }
        objective -= c.targetNormalVelocity * s.change[k][0];
    }
    return objective;
}

} // namespace

bool stepOnActiveSet(std::span<ContactConstraint> constraints, std::span<SolverBody> bodies,
                     int iterations, int& budget, Real velocityTolerance)
{
    thread_local ActiveSetScratch scratch;
    ActiveSetScratch& s = scratch;
    gatherRows(constraints, bodies, s);
    if (s.rows.empty()) {
        return false;
    }
    s.saved.assign(bodies.begin(), bodies.end());
    conjugateGradients(constraints, iterations, velocityTolerance, budget, s);
    // the projected step, then its half, quarter and eighth: the first that lowers the
    // objective is kept (a backtracking line search along the step)
    bool lowered = false;
    for (int halving = 0; halving < kHalvings && !lowered; ++halving) {
        if (halving > 0) {
            for (Real& x : s.solution) {
                x *= 0.5;
            }
        }
        projectStep(constraints, bodies, s);
        lowered = applyStep(constraints, bodies, s) < 0.0;
        if (!lowered) {
            std::copy(s.saved.begin(), s.saved.end(), bodies.begin());
        }
    }
    if (!lowered) {
        return false;
    }
    for (std::size_t k = 0; k < constraints.size(); ++k) {
        ContactConstraint& c = constraints[k];
        c.normalImpulse = s.next[k][0];
        c.tangentImpulse1 = s.next[k][1];
        c.tangentImpulse2 = s.next[k][2];
        c.normalWork += s.work[k][0];
        c.frictionWork += s.work[k][1] + s.work[k][2];
    }
    return true;
}

} // namespace tumble
