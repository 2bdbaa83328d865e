// Preparing and sweeping the points of a solve at one cuboid's touching vertices
// (Catto 2005/2014; Mirtich 1996).
#include "dynamics/plane_sweeps.hpp"

#include "body_state.hpp"
#include "dynamics/friction_cone.hpp"
#include "dynamics/normal_impulses.hpp"
#include "dynamics/sweep_accelerator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

namespace tumble {

namespace {

/// A friction impulse whose component along its point's sliding exceeds this fraction of the
/// solve's speed scale is driving the sliding (5.13).
constexpr Real kDrivingSpeed = 1e-6;
/// Most alternations of the normal and the friction problems after a capped solve whose friction
/// drives sliding (5.13), and the friction sweeps in each: the alternation converges linearly, so
/// friction solved further with normal impulses that are still moving is wasted work.
constexpr int kStaggeredPasses = 64;
constexpr int kStaggeredFrictionSweeps = 4;

/// Sweeps in a row that have not halved the change of the sweep before them: the solve has
/// stalled and ends as at the cap (5.15). A solve that converges within the cap from a change of
/// order 1 to 1e-10 halves it at least every 7 sweeps on average.
constexpr int kStalledSweeps = 32;

/// The friction impulse of one point with the others held fixed (6.4), friction_cone.hpp.
void solveFriction(SolverPoint& point, Real v1, Real v2, Real& impulse1, Real& impulse2)
{
    const FrictionImpulse result =
        frictionOnCone(point.tangentK, point.tangentMass, point.tangentImpulse1,
                       point.tangentImpulse2, point.friction * point.normalImpulse, v1, v2,
                       point.frictionShift);
    impulse1 = result.impulse1;
    impulse2 = result.impulse2;
}

/// (5.11): replaces the normal impulses by the exact solution of the normal problem with the
/// friction impulses held, for a solve that ran out of sweeps.
void solveNormalExactly(Body& body, const SolverFrame& frame, std::span<SolverPoint> points,
                        Real targetScale)
{
    std::array<Vec3, 8> offsets{};
    std::array<Real, 8> freeVelocities{};
    for (std::size_t i = 0; i < points.size(); ++i) {
        SolverPoint& point = points[i];
        applyImpulseAtOffset(body, -point.normalImpulse * frame.n, point.r);
        point.normalImpulse = 0.0;
        offsets[i] = point.r;
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec3 velocity = body.linearVelocity + glm::cross(body.angularVelocity, points[i].r);
        freeVelocities[i] =
            glm::dot(frame.n, velocity) - targetScale * points[i].targetNormalVelocity;
    }
    const std::array<Real, 8> impulses =
        solveNormalImpulses(body.invMass, body.invInertiaWorld, frame.n,
                            std::span(offsets.data(), points.size()),
                            std::span(freeVelocities.data(), points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
        points[i].normalImpulse = impulses[i];
        applyImpulseAtOffset(body, impulses[i] * frame.n, points[i].r);
    }
}

/// One point's friction step (6.4) applied to the body; returns the largest change of its two
/// impulse components.
Real updateFriction(Body& body, const SolverFrame& frame, SolverPoint& point)
{
    const Vec3 velocity = body.linearVelocity + glm::cross(body.angularVelocity, point.r);
    Real candidate1 = 0.0;
    Real candidate2 = 0.0;
    solveFriction(point, glm::dot(frame.t1, velocity), glm::dot(frame.t2, velocity), candidate1,
                  candidate2);
    const Real change1 = candidate1 - point.tangentImpulse1;
    const Real change2 = candidate2 - point.tangentImpulse2;
    point.tangentImpulse1 = candidate1;
    point.tangentImpulse2 = candidate2;
    body.linearVelocity += body.invMass * (change1 * frame.t1 + change2 * frame.t2);
    body.angularVelocity += change1 * point.angularPerTangent1 + change2 * point.angularPerTangent2;
    return std::max(std::abs(change1), std::abs(change2));
}

/// (5.13): friction alone, with the normal impulses held. Each point's step (6.4) is the exact
/// minimiser of the kinetic energy over its own disc, and the discs no longer move, so the
/// sweeps are block coordinate descent on a convex problem and converge, where the full sweeps
/// may cycle because every normal impulse moves the other points' cones.
void solveFrictionWithNormalsHeld(Body& body, const SolverFrame& frame,
                                  std::span<SolverPoint> points, int iterations, Real convergence)
{
    for (int iteration = 0; iteration < iterations; ++iteration) {
        Real largestChange = 0.0;
        Real largestImpulse = 0.0;
        for (SolverPoint& point : points) {
            largestChange = std::max(largestChange, updateFriction(body, frame, point));
            largestImpulse = std::max(
                {largestImpulse, point.normalImpulse,
                 planarLength(point.tangentImpulse1, point.tangentImpulse2)});
        }
        if (largestChange <= convergence * largestImpulse) {
            return;
        }
    }
}

/// Whether a point's friction impulse has a component along its own sliding velocity, beyond
/// rounding relative to `speedScale` (the fastest point before the solve): Coulomb friction
/// never does that (6.1), so a solve that ends so has not found the solution (5.13).
bool frictionDrivesSliding(const Body& body, const SolverFrame& frame,
                           std::span<const SolverPoint> points, Real speedScale)
{
    for (const SolverPoint& point : points) {
        const Vec3 velocity = body.linearVelocity + glm::cross(body.angularVelocity, point.r);
        const Real sliding1 = glm::dot(frame.t1, velocity);
        const Real sliding2 = glm::dot(frame.t2, velocity);
        const Real power = point.tangentImpulse1 * sliding1 + point.tangentImpulse2 * sliding2;
        if (power > kDrivingSpeed * speedScale *
                        planarLength(point.tangentImpulse1, point.tangentImpulse2)) {
            return true;
        }
    }
    return false;
}

/// Scales each friction impulse back into the cone of its point's normal impulse (6.2).
void clampFrictionToCone(Body& body, const SolverFrame& frame, std::span<SolverPoint> points)
{
    for (SolverPoint& point : points) {
        const FrictionImpulse inCone = scaledIntoDisc(
            point.tangentImpulse1, point.tangentImpulse2, point.friction * point.normalImpulse);
        const Real change1 = inCone.impulse1 - point.tangentImpulse1;
        const Real change2 = inCone.impulse2 - point.tangentImpulse2;
        if (change1 == 0.0 && change2 == 0.0) {
            continue;
        }
        point.tangentImpulse1 = inCone.impulse1;
        point.tangentImpulse2 = inCone.impulse2;
        applyImpulseAtOffset(body, change1 * frame.t1 + change2 * frame.t2, point.r);
    }
}

} // namespace


/// Writes every field of `point` (in place: a point is a quarter of a kilobyte, and building it
/// zeroed and copying it cost as much as the arithmetic below).
void preparePoint(SolverPoint& point, const Body& body, const SolverFrame& frame, const Vec3& r,
                  Real restitution, Real restitutionThreshold)
{
    point.r = r;
    const Mat3& invInertia = body.invInertiaWorld;
    // (5.2): K_n = 1/m + (r x n) . I^-1 (r x n).
    const Vec3 rn = glm::cross(r, frame.n);
    point.angularPerNormal = invInertia * rn;
    point.normalMass = 1.0 / (body.invMass + glm::dot(rn, point.angularPerNormal));
    // (6.3): K_t,ab = delta_ab/m + (r x t_a) . I^-1 (r x t_b), inverted in closed form.
    const Vec3 r1 = glm::cross(r, frame.t1);
    const Vec3 r2 = glm::cross(r, frame.t2);
    point.angularPerTangent1 = invInertia * r1;
    point.angularPerTangent2 = invInertia * r2;
    const Real k11 = body.invMass + glm::dot(r1, point.angularPerTangent1);
    const Real k22 = body.invMass + glm::dot(r2, point.angularPerTangent2);
    const Real k12 = glm::dot(r1, point.angularPerTangent2);
    const Real invDeterminant = 1.0 / (k11 * k22 - k12 * k12);
    point.tangentK = {k11, k12, k12, k22};
    point.tangentMass = {k22 * invDeterminant, -k12 * invDeterminant, -k12 * invDeterminant,
                         k11 * invDeterminant};

    const Vec3 velocity = body.linearVelocity + glm::cross(body.angularVelocity, r);
    point.velocityBefore = velocity;
    point.normalImpulse = 0.0;
    point.tangentImpulse1 = 0.0;
    point.tangentImpulse2 = 0.0;
    point.frictionShift = 0.0;
    point.targetNormalVelocity = 0.0;
    point.restitution = RestitutionState::None;
    const Real normalVelocity = glm::dot(frame.n, velocity);
    if (normalVelocity < -restitutionThreshold) {
        point.targetNormalVelocity = -restitution * normalVelocity;
        point.restitution = RestitutionState::Applied;
    } else if (normalVelocity < 0.0 && restitution > 0.0) {
        point.restitution = RestitutionState::Suppressed;
    }
    const Vec3 sliding = velocity - normalVelocity * frame.n;
    point.friction = lengthSquared(sliding) < kStickingSpeedSquared
                         ? body.material.staticFrictionOrKinetic()
                         : body.material.friction;
}

/// Gauss-Seidel over the points, friction then normal at each (normal last so non-penetration
/// wins), accumulated impulses clamped to the cone |lambda_t| <= mu lambda_n (6.2) and
/// lambda_n >= 0 (5.4). `targetScale` scales every restitution target (5.6). With `accelerate`
/// the sweeps are extrapolated (5.14); without, each sweep lowers the solve's objective, which
/// the energy guard (5.12) relies on. Sweeps that have not converged at the cap end with the
/// exact normal impulses (5.11).
void solvePoints(Body& body, const SolverFrame& frame, std::span<SolverPoint> points,
                 Real targetScale, int iterations, Real convergence, bool accelerate)
{
    // Kept for the speed scale of (5.13), needed only if the sweeps reach the cap.
    const Vec3 linearVelocityStart = body.linearVelocity;
    const Vec3 angularVelocityStart = body.angularVelocity;
    SweepAccelerator accelerator;
    // (5.15): the relative change of the sweep at which the change last halved, and the sweeps
    // since then.
    Real halvingChange = std::numeric_limits<Real>::infinity();
    int sweepsSinceHalving = 0;
    for (int iteration = 0; iteration < iterations; ++iteration) {
        Real largestChange = 0.0;
        Real largestImpulse = 0.0;
        if (accelerate) {
            accelerator.recordStart(points);
        }
        for (SolverPoint& point : points) {
            const Real frictionChange = updateFriction(body, frame, point);

            const Vec3 velocity = body.linearVelocity + glm::cross(body.angularVelocity, point.r);
            const Real normalVelocity = glm::dot(frame.n, velocity);
            const Real target = targetScale * point.targetNormalVelocity;
            const Real candidate =
                std::max(0.0, point.normalImpulse + point.normalMass * (target - normalVelocity));
            const Real change = candidate - point.normalImpulse;
            point.normalImpulse = candidate;
            body.linearVelocity += (body.invMass * change) * frame.n;
            body.angularVelocity += change * point.angularPerNormal;

            largestChange = std::max({largestChange, std::abs(change), frictionChange});
            largestImpulse = std::max(largestImpulse, point.normalImpulse);
        }
        if (largestChange <= convergence * largestImpulse) {
            return;
        }
        // (5.15): sweeps whose change has stopped shrinking (a cycle, or impulses drifting along
        // a split of the load among redundant points) would only run on to the cap.
        const Real relativeChange = largestChange / largestImpulse;
        if (relativeChange <= 0.5 * halvingChange) {
            halvingChange = relativeChange;
            sweepsSinceHalving = 0;
        } else if (++sweepsSinceHalving >= kStalledSweeps) {
            break;
        }
        if (accelerate) {
            accelerator.extrapolate(body, frame, points);
        }
    }
    // (5.11): a contact patch much longer than it is wide (a plate on its edge) makes
    // Gauss-Seidel converge so slowly that the cap leaves vertices approaching, and the push-out
    // (4.5) then turns the depth into potential energy. Normal last, as in a sweep.
    const auto endWithExactNormals = [&] {
        solveNormalExactly(body, frame, points, targetScale);
        clampFrictionToCone(body, frame, points);
        solveNormalExactly(body, frame, points, targetScale);
    };
    endWithExactNormals();
    Real speedScale = 0.0;
    for (const SolverPoint& point : points) {
        speedScale = std::max(speedScale, glm::length(linearVelocityStart +
                                                      glm::cross(angularVelocityStart, point.r)));
    }
    if (!frictionDrivesSliding(body, frame, points, speedScale)) {
        return;
    }
    // (5.13): friction at the face tilts the body and so moves the other points' cones; far
    // above a friction of the patch's width over the height of the centre the sweeps cycle,
    // and the last sweep's friction can drive the sliding it should resist. The normal problem
    // (exactly) and the friction problem with the normal impulses held (convex, a few sweeps)
    // then take turns until the velocities, unique where the split of the impulses among
    // redundant corners is not, stop changing.
    for (int pass = 0; pass < kStaggeredPasses; ++pass) {
        const Vec3 linearBefore = body.linearVelocity;
        const Vec3 angularBefore = body.angularVelocity;
        solveNormalExactly(body, frame, points, targetScale);
        solveFrictionWithNormalsHeld(body, frame, points, kStaggeredFrictionSweeps, convergence);
        Real largestChange = 0.0;
        for (const SolverPoint& point : points) {
            largestChange = std::max(
                largestChange, glm::length(body.linearVelocity - linearBefore +
                                           glm::cross(body.angularVelocity - angularBefore,
                                                      point.r)));
        }
        if (largestChange <= convergence * speedScale) {
            break;
        }
    }
    endWithExactNormals();
}

} // namespace tumble
