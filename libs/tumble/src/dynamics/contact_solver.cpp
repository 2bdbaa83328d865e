// Sequential impulses at the touching vertices of one cuboid (Catto 2005/2014; Mirtich 1996).
#include "dynamics/contact_solver.hpp"

#include "body_state.hpp"
#include "dynamics/friction_cone.hpp"
#include "dynamics/normal_impulses.hpp"
#include "tumble_assert.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

namespace tumble {

namespace {

/// Below this sliding speed a vertex sticks, and the static coefficient bounds its friction, m/s.
/// Compared as squares: the square root was a tenth of preparing a point.
constexpr Real kStickingSpeed = 1e-3;
constexpr Real kStickingSpeedSquared = kStickingSpeed * kStickingSpeed;
/// A solve has converged when no impulse changed by more than this fraction of the largest in a
/// sweep. Impacts are rare and decide the bounce, so they go to the rounding noise of a sweep
/// (about 1e-13). Resting solves are most of the cost of many bodies: a warm-started one reaches
/// 1e-10 in a sweep or two, and a rocking or sliding body, where Gauss-Seidel converges slowly,
/// in far fewer sweeps than at 1e-12 (docs/physics/05-normal-impulse.md, (5.10)).
constexpr Real kImpactConvergence = 1e-13;
constexpr Real kRestingConvergence = 1e-10;
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

/// The depth-two fit of (5.14) falls back to depth one when the two residual differences are
/// this close to parallel (det <= this times the product of their squared lengths).
constexpr Real kAndersonConditioning = 1e-10;

/// Length of (a, b). Impulses and velocities are far from overflow, so this skips the scaling
/// std::hypot does (which made it the solver's single largest cost).
Real planarLength(Real a, Real b) { return std::sqrt(a * a + b * b); }

/// Per-vertex data of a solve: the offset, the effective masses and the accumulated impulses
/// (symbols of docs/physics/05-normal-impulse.md and 06-friction.md). No member initialisers, so
/// a solve's unused points cost nothing; preparePoint writes every field of the ones it uses.
struct SolverPoint {
    Vec3 r;
    /// I^-1 (r x n), I^-1 (r x t1), I^-1 (r x t2): the change of angular velocity per unit
    /// impulse along each direction, computed once so a sweep applies an impulse with two
    /// scaled additions instead of a cross product and a matrix product (Catto 2005).
    Vec3 angularPerNormal;
    Vec3 angularPerTangent1;
    Vec3 angularPerTangent2;
    Real normalMass;
    /// The 2x2 tangential matrix K_t (6.3) and its inverse, the effective mass; row-major.
    std::array<Real, 4> tangentK;
    std::array<Real, 4> tangentMass;
    /// Target normal velocity: -e vn^- for an impact faster than the threshold, else 0 (5.3).
    Real targetNormalVelocity;
    Real friction;
    /// Velocity of the material point at the vertex when the solve was prepared.
    Vec3 velocityBefore;
    RestitutionState restitution;
    Real normalImpulse;
    Real tangentImpulse1;
    Real tangentImpulse2;
    /// The shift s of the last friction solve on the cone's edge (6.4), where the next sweep's
    /// Newton iteration starts: the edge solution moves little from sweep to sweep.
    Real frictionShift;
};

struct SolverFrame {
    Vec3 n{0.0, 1.0, 0.0};
    Vec3 t1{1.0, 0.0, 0.0};
    Vec3 t2{0.0, 0.0, 1.0};
};

SolverFrame makeFrame(const Vec3& normal)
{
    SolverFrame frame;
    frame.n = normal;
    orthonormalBasis(normal, frame.t1, frame.t2);
    return frame;
}

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
        const Real bound = point.friction * point.normalImpulse;
        const Real magnitude = planarLength(point.tangentImpulse1, point.tangentImpulse2);
        if (magnitude <= bound) {
            continue;
        }
        const Real scale = bound / magnitude;
        const Real change1 = (scale - 1.0) * point.tangentImpulse1;
        const Real change2 = (scale - 1.0) * point.tangentImpulse2;
        point.tangentImpulse1 += change1;
        point.tangentImpulse2 += change2;
        applyImpulseAtOffset(body, change1 * frame.t1 + change2 * frame.t2, point.r);
    }
}

/// Every impulse of a solve, three per point: normal, tangent 1, tangent 2.
using ImpulseVector = std::array<Real, 24>;

/// (5.14): Anderson acceleration of depth two over the sweeps (Anderson 1965; Walker & Ni 2011).
/// A sweep is a map x -> G(x) of the impulses, and on a die's contact it contracts by a steady
/// factor of 0.3 to 0.9 a sweep. From the last three sweeps' images g and residuals f = G(x) - x
/// the next iterate is g_k - dG gamma, with gamma the least-squares fit of the residual
/// differences dF to f_k: exact for a linear map with two dominant modes, and a plain sweep
/// again (the history dropped) whenever a sweep fails to shrink the residual, as at a change of
/// which points push or slide. Only the iterate moves: every solve still ends on a sweep of its
/// own that met the convergence test, or on (5.11) at the cap.
class SweepAccelerator {
public:
    /// Keeps x_k, the impulses before the sweep.
    void recordStart(std::span<const SolverPoint> points)
    {
        m_size = 3 * points.size();
        for (std::size_t i = 0; i < points.size(); ++i) {
            m_start[3 * i] = points[i].normalImpulse;
            m_start[3 * i + 1] = points[i].tangentImpulse1;
            m_start[3 * i + 2] = points[i].tangentImpulse2;
        }
    }

    /// Moves the impulses (and the body with them) from the sweep's image to the extrapolation.
    void extrapolate(Body& body, const SolverFrame& frame, std::span<SolverPoint> points)
    {
        ImpulseVector& image = m_images[m_newest ^ 1];
        ImpulseVector& residual = m_residuals[m_newest ^ 1];
        Real residualNorm = 0.0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            image[3 * i] = points[i].normalImpulse;
            image[3 * i + 1] = points[i].tangentImpulse1;
            image[3 * i + 2] = points[i].tangentImpulse2;
        }
        for (std::size_t j = 0; j < m_size; ++j) {
            residual[j] = image[j] - m_start[j];
            residualNorm = std::max(residualNorm, std::abs(residual[j]));
        }
        if (!(residualNorm < m_residualNorm)) {
            m_depth = 0;
        }
        Real gamma1 = 0.0;
        Real gamma2 = 0.0;
        if (fit(residual, gamma1, gamma2)) {
            const ImpulseVector& image1 = m_images[m_newest];
            const ImpulseVector& image2 = m_images[2];
            for (std::size_t i = 0; i < points.size(); ++i) {
                std::array<Real, 3> next{};
                for (std::size_t c = 0; c < 3; ++c) {
                    const std::size_t j = 3 * i + c;
                    next[c] = image[j] - gamma1 * (image[j] - image1[j]);
                    if (m_depth >= 2) {
                        next[c] -= gamma2 * (image1[j] - image2[j]);
                    }
                }
                SolverPoint& point = points[i];
                next[0] = std::max(0.0, next[0]);
                applyImpulseAtOffset(body,
                                     (next[0] - point.normalImpulse) * frame.n +
                                         (next[1] - point.tangentImpulse1) * frame.t1 +
                                         (next[2] - point.tangentImpulse2) * frame.t2,
                                     point.r);
                point.normalImpulse = next[0];
                point.tangentImpulse1 = next[1];
                point.tangentImpulse2 = next[2];
            }
        }
        // The newest becomes the middle entry, the middle one the oldest (slot 2).
        if (m_depth >= 1) {
            std::copy_n(m_images[m_newest].begin(), m_size, m_images[2].begin());
            std::copy_n(m_residuals[m_newest].begin(), m_size, m_residuals[2].begin());
        }
        m_newest ^= 1;
        m_residualNorm = residualNorm;
        m_depth = std::min(m_depth + 1, 2);
    }

private:
    /// The least-squares gamma of depth m_depth (two if its normal equations are well
    /// conditioned, else one); false when there is no history to fit.
    bool fit(const ImpulseVector& residual, Real& gamma1, Real& gamma2) const
    {
        if (m_depth == 0) {
            return false;
        }
        const ImpulseVector& residual1 = m_residuals[m_newest];
        const ImpulseVector& residual2 = m_residuals[2];
        Real a11 = 0.0;
        Real a12 = 0.0;
        Real a22 = 0.0;
        Real b1 = 0.0;
        Real b2 = 0.0;
        for (std::size_t j = 0; j < m_size; ++j) {
            const Real d1 = residual[j] - residual1[j];
            const Real d2 = m_depth >= 2 ? residual1[j] - residual2[j] : 0.0;
            a11 += d1 * d1;
            a12 += d1 * d2;
            a22 += d2 * d2;
            b1 += d1 * residual[j];
            b2 += d2 * residual[j];
        }
        const Real determinant = a11 * a22 - a12 * a12;
        if (m_depth >= 2 && determinant > kAndersonConditioning * a11 * a22) {
            gamma1 = (a22 * b1 - a12 * b2) / determinant;
            gamma2 = (a11 * b2 - a12 * b1) / determinant;
            return true;
        }
        if (a11 > 0.0) {
            gamma1 = b1 / a11;
            return true;
        }
        return false;
    }

    /// Not initialised (a solve that converges in a sweep or two, most of them, would pay for
    /// zeroing a kilobyte): only the first m_size entries are used, each written first, and the
    /// slot-2 entries only at depth two, after the copy that fills them.
    ImpulseVector m_start;
    /// Images and residuals of the last sweeps: m_newest (0 or 1) holds the last, slot 2 the one
    /// before; the other of 0 and 1 receives the sweep in hand.
    std::array<ImpulseVector, 3> m_images;
    std::array<ImpulseVector, 3> m_residuals;
    std::size_t m_size = 0;
    Real m_residualNorm = std::numeric_limits<Real>::infinity();
    int m_newest = 0;
    int m_depth = 0;
};

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

/// The points of one solve. Only the first `count` are ever written or read: the others are
/// left uninitialised, since zeroing eight points (2 kB) cost more than preparing four.
struct PreparedSolve {
    PreparedSolve() = default;
    PreparedSolve(const PreparedSolve&) = delete;
    PreparedSolve& operator=(const PreparedSolve&) = delete;

    SolverFrame frame;
    std::array<SolverPoint, 8> points;
    int count = 0;
};

void prepare(PreparedSolve& solve, const Body& body, const ContactManifold& manifold,
             Real restitution, Real restitutionThreshold)
{
    solve.frame = makeFrame(manifold.normal);
    solve.count = 0;
    for (int i = 0; i < manifold.pointCount; ++i) {
        preparePoint(solve.points[solve.count++], body, solve.frame,
                     manifold.points[i].position - body.position, restitution,
                     restitutionThreshold);
    }
}

/// Takes a solve back to its start: a solve changes only the points' impulses and friction
/// shifts, so zeroing them is the prepared state again (without copying eight points).
void restartFromZero(PreparedSolve& solve)
{
    for (int i = 0; i < solve.count; ++i) {
        SolverPoint& point = solve.points[i];
        point.normalImpulse = 0.0;
        point.tangentImpulse1 = 0.0;
        point.tangentImpulse2 = 0.0;
        point.frictionShift = 0.0;
    }
}

/// Copies the accumulated impulses into the manifold and sums them into the outcome.
void publish(const PreparedSolve& solve, const Body& body, ContactManifold& manifold,
             ImpactOutcome& outcome)
{
    outcome.normalImpulse = Vec3(0.0);
    outcome.frictionImpulse = Vec3(0.0);
    outcome.work = ContactWork{};
    for (int i = 0; i < solve.count; ++i) {
        const SolverPoint& point = solve.points[i];
        ContactPoint& published = manifold.points[i];
        published.normalImpulse = point.normalImpulse;
        published.frictionImpulse =
            point.tangentImpulse1 * solve.frame.t1 + point.tangentImpulse2 * solve.frame.t2;
        published.velocityBefore = point.velocityBefore;
        published.velocityAfter = body.velocityAt(published.position);
        published.restitution = point.restitution;
        const Vec3 slidingAfter =
            published.velocityAfter - glm::dot(solve.frame.n, published.velocityAfter) * solve.frame.n;
        published.sliding =
            point.normalImpulse > 0.0 && lengthSquared(slidingAfter) > kStickingSpeedSquared;
        outcome.normalImpulse += point.normalImpulse * solve.frame.n;
        outcome.frictionImpulse += published.frictionImpulse;
        // (8.2): with the final impulses and the point's velocity before and after, the sum over
        // the points is exactly the kinetic energy the solve changed, whatever path Gauss-Seidel
        // took; before is taken ahead of gravity's impulse, so a resting body does no work.
        const Vec3 meanVelocity = 0.5 * (published.velocityBefore + published.velocityAfter);
        outcome.work.normal += point.normalImpulse * glm::dot(solve.frame.n, meanVelocity);
        outcome.work.friction += glm::dot(published.frictionImpulse, meanVelocity);
    }
}

} // namespace

Real approachSpeed(const Body& body, const ContactManifold& manifold)
{
    Real fastest = 0.0;
    for (int i = 0; i < manifold.pointCount; ++i) {
        const Real normalVelocity =
            glm::dot(manifold.normal, body.velocityAt(manifold.points[i].position));
        fastest = std::max(fastest, -normalVelocity);
    }
    return fastest;
}

ImpactOutcome resolveImpact(Body& body, ContactManifold& manifold,
                            const ContactSolveSettings& settings)
{
    ImpactOutcome outcome;
    outcome.approachSpeed = approachSpeed(body, manifold);
    outcome.kineticEnergyBefore = body.kineticEnergy();
    const Vec3 velocityBefore = body.linearVelocity;
    const Vec3 angularVelocityBefore = body.angularVelocity;
    PreparedSolve solve;
    prepare(solve, body, manifold, body.material.restitution, settings.restitutionThreshold);
    outcome.restitution = body.material.restitution;
    for (int i = 0; i < solve.count; ++i) {
        // Newton's law applies to a point faster than the threshold, whatever e (e = 0 included)
        outcome.restitutionApplied |= solve.points[i].restitution == RestitutionState::Applied;
    }
    solvePoints(body, solve.frame, std::span(solve.points.data(), solve.count), 1.0,
                settings.iterations, kImpactConvergence, true);
    // (5.6): Newton's law at several points, or with sticking friction, can create energy. If it
    // did, scale the restitution targets down (bisection) to the largest that does not.
    const Real allowed = outcome.kineticEnergyBefore * (1.0 + 1e-12);
    if (body.kineticEnergy() > allowed) {
        Real keep = 0.0;
        Real reject = 1.0;
        for (int halving = 0; halving < 40; ++halving) {
            const Real scale = 0.5 * (keep + reject);
            body.linearVelocity = velocityBefore;
            body.angularVelocity = angularVelocityBefore;
            restartFromZero(solve);
            solvePoints(body, solve.frame, std::span(solve.points.data(), solve.count), scale,
                        settings.iterations, kImpactConvergence, true);
            (body.kineticEnergy() > allowed ? reject : keep) = scale;
        }
        body.linearVelocity = velocityBefore;
        body.angularVelocity = angularVelocityBefore;
        restartFromZero(solve);
        solvePoints(body, solve.frame, std::span(solve.points.data(), solve.count), keep,
                    settings.iterations, kImpactConvergence, true);
    }
    publish(solve, body, manifold, outcome);
    outcome.kineticEnergyAfter = body.kineticEnergy();
    return outcome;
}

ContactWork solveRestingContact(Body& body, ContactManifold& manifold,
                                const Vec3& gravityImpulsePerMass, Real tau,
                                const ContactSolveSettings& settings,
                                const WarmStartCache& warmStart)
{
    // (5.9) divides by tau: a sub-step has positive length. A NaN tau passes: it comes from a
    // state already non-finite, which the caller reports (docs/robustness.md), not a zero step.
    TUMBLE_ASSERT(!(tau <= 0.0));
    // Prepared before gravity acts, so a body at rest on a slope sees no sliding and keeps the
    // static coefficient.
    PreparedSolve solve;
    prepare(solve, body, manifold, 0.0, settings.restitutionThreshold);
    body.linearVelocity += gravityImpulsePerMass;
    if (solve.count == 0) {
        return ContactWork{};
    }
    for (int i = 0; i < solve.count; ++i) {
        // (5.9): the target -h / tau lets a vertex at height h reach the plane, no further.
        solve.points[i].targetNormalVelocity =
            -std::max(0.0, -manifold.points[i].penetration) / tau;
        solve.points[i].restitution = RestitutionState::None;
    }
    const Vec3 freeVelocity = body.linearVelocity;
    const Vec3 freeAngularVelocity = body.angularVelocity;
    // (5.12): with targets <= 0 the solution never has more kinetic energy than the body had
    // without contact; rounding aside, more means the solve did not reach it.
    const Real allowed =
        body.kineticEnergy() * (1.0 + 1e-12) + std::numeric_limits<Real>::min();
    for (int i = 0; i < solve.count; ++i) {
        SolverPoint& point = solve.points[i];
        // (5.10): start from last step's impulse rates at this vertex, inside the cone.
        const int vertex = manifold.points[i].vertex;
        if (((warmStart.vertices >> vertex) & 1u) == 0u) {
            continue;
        }
        point.normalImpulse = std::max(0.0, warmStart.normalRate[vertex] * tau);
        const Vec3 friction = warmStart.frictionRate[vertex] * tau;
        point.tangentImpulse1 = glm::dot(friction, solve.frame.t1);
        point.tangentImpulse2 = glm::dot(friction, solve.frame.t2);
        const Real bound = point.friction * point.normalImpulse;
        const Real magnitude = planarLength(point.tangentImpulse1, point.tangentImpulse2);
        if (magnitude > bound) {
            point.tangentImpulse1 *= bound / magnitude;
            point.tangentImpulse2 *= bound / magnitude;
        }
        applyImpulseAtOffset(body,
                             point.normalImpulse * solve.frame.n +
                                 point.tangentImpulse1 * solve.frame.t1 +
                                 point.tangentImpulse2 * solve.frame.t2,
                             point.r);
    }
    solvePoints(body, solve.frame, std::span(solve.points.data(), solve.count), 1.0,
                settings.iterations, kRestingConvergence, true);
    // (5.12): a warm start the sweeps could not take back in time, or friction scaled into its
    // cone after the cap (5.11), can leave more energy than the body had. Sweeps started from
    // zero only lower the solve's objective, which bounds the energy; without friction, the
    // exact normal impulses at the cap (5.11) keep that bound too.
    for (const bool withFriction : {true, false}) {
        if (body.kineticEnergy() <= allowed) {
            break;
        }
        body.linearVelocity = freeVelocity;
        body.angularVelocity = freeAngularVelocity;
        restartFromZero(solve);
        for (int i = 0; i < solve.count && !withFriction; ++i) {
            solve.points[i].friction = 0.0;
        }
        solvePoints(body, solve.frame, std::span(solve.points.data(), solve.count), 1.0,
                    settings.iterations, kRestingConvergence, false);
    }
    ImpactOutcome outcome;
    publish(solve, body, manifold, outcome);
    return outcome.work;
}

WarmStartCache makeWarmStart(const ContactManifold& manifold, Real tau)
{
    WarmStartCache cache;
    for (int i = 0; i < manifold.pointCount; ++i) {
        const ContactPoint& point = manifold.points[i];
        cache.normalRate[point.vertex] = point.normalImpulse / tau;
        cache.frictionRate[point.vertex] = point.frictionImpulse / tau;
        cache.vertices = static_cast<std::uint8_t>(cache.vertices | (1u << point.vertex));
    }
    return cache;
}

ImpactOutcome resolveAverageContact(Body& body, ContactManifold& manifold,
                                    const ContactSolveSettings& settings)
{
    ImpactOutcome outcome;
    outcome.kineticEnergyBefore = body.kineticEnergy();
    outcome.kineticEnergyAfter = outcome.kineticEnergyBefore;
    if (manifold.pointCount == 0) {
        return outcome;
    }
    for (int i = 0; i < manifold.pointCount; ++i) {
        manifold.points[i].velocityBefore = body.velocityAt(manifold.points[i].position);
        manifold.points[i].velocityAfter = manifold.points[i].velocityBefore;
    }
    const Vec3& n = manifold.normal;
    const Vec3 r = manifold.averagePoint() - body.position;
    const Vec3 velocity = body.velocityAt(manifold.averagePoint());
    const Real normalVelocity = glm::dot(n, velocity);
    if (normalVelocity >= 0.0) {
        return outcome;
    }
    outcome.approachSpeed = -normalVelocity;
    outcome.restitutionApplied = -normalVelocity > settings.restitutionThreshold;
    outcome.restitution = body.material.restitution;
    const Real restitution = outcome.restitutionApplied ? body.material.restitution : 0.0;
    // (5.7): j = -(1 + e) vn / (1/m + (r x n) . I^-1 (r x n)).
    const Vec3 rn = glm::cross(r, n);
    const Real normalImpulse =
        -(1.0 + restitution) * normalVelocity /
        (body.invMass + glm::dot(rn, body.invInertiaWorld * rn));
    // Friction along the sliding direction, at most mu j and at most what stops the sliding.
    const Vec3 sliding = velocity - normalVelocity * n;
    const Real slidingSpeed = glm::length(sliding);
    Vec3 frictionImpulse(0.0);
    Real friction = body.material.friction;
    if (slidingSpeed > 0.0) {
        const Vec3 t = sliding / slidingSpeed;
        const Vec3 rt = glm::cross(r, t);
        const Real stoppingImpulse =
            slidingSpeed / (body.invMass + glm::dot(rt, body.invInertiaWorld * rt));
        friction = slidingSpeed < kStickingSpeed ? body.material.staticFrictionOrKinetic()
                                                 : body.material.friction;
        frictionImpulse = -std::min(friction * normalImpulse, stoppingImpulse) * t;
    }
    outcome.normalImpulse = normalImpulse * n;
    outcome.frictionImpulse = frictionImpulse;
    applyImpulseAtOffset(body, outcome.normalImpulse + frictionImpulse, r);
    // (8.2) for the one impulse, split into its normal and tangential parts.
    const Vec3 meanVelocity = 0.5 * (velocity + body.velocityAt(manifold.averagePoint()));
    outcome.work.normal = glm::dot(outcome.normalImpulse, meanVelocity);
    outcome.work.friction = glm::dot(frictionImpulse, meanVelocity);
    outcome.kineticEnergyAfter = body.kineticEnergy();
    // The points share the one impulse equally, for the contact ledger.
    const Real share = 1.0 / static_cast<Real>(manifold.pointCount);
    for (int i = 0; i < manifold.pointCount; ++i) {
        ContactPoint& point = manifold.points[i];
        point.normalImpulse = share * normalImpulse;
        point.frictionImpulse = share * frictionImpulse;
        point.velocityAfter = body.velocityAt(point.position);
        point.restitution = outcome.restitutionApplied ? RestitutionState::Applied
                                                       : RestitutionState::Suppressed;
        point.sliding = glm::length(frictionImpulse) >= friction * normalImpulse * (1.0 - 1e-12) &&
                        friction * normalImpulse > 0.0;
    }
    return outcome;
}

} // namespace tumble
