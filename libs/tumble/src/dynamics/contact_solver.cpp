// Sequential impulses at the touching vertices of one cuboid: the impact, resting-contact and
// handouts' solves (Catto 2005/2014; Mirtich 1996).
#include "dynamics/contact_solver.hpp"

#include "body_state.hpp"
#include "dynamics/friction_cone.hpp"
#include "dynamics/plane_sweeps.hpp"
#include "dynamics/solver_point.hpp"
#include "tumble_assert.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

namespace tumble {

namespace {

/// A solve has converged when no impulse changed by more than this fraction of the largest in a
/// sweep. Impacts are rare and decide the bounce, so they go to the rounding noise of a sweep
/// (about 1e-13). Resting solves are most of the cost of many bodies: a warm-started one reaches
/// 1e-10 in a sweep or two, and a rocking or sliding body, where Gauss-Seidel converges slowly,
/// in far fewer sweeps than at 1e-12 (docs/physics/05-normal-impulse.md, (5.10)).
constexpr Real kImpactConvergence = 1e-13;
constexpr Real kRestingConvergence = 1e-10;

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

/// The resting solve's objective less its value at no impulse, f(lambda) - f(0) = T - T(0) -
/// lambda_n . t (5.12), from the body's kinetic energy now and `freeKinetic` = T(0).
Real restingObjective(const PreparedSolve& solve, const Body& body, Real freeKinetic)
{
    Real targetsWork = 0.0;
    for (int i = 0; i < solve.count; ++i) {
        targetsWork += solve.points[i].normalImpulse * solve.points[i].targetNormalVelocity;
    }
    return body.kineticEnergy() - freeKinetic - targetsWork;
}

/// (5.12a): the impulses without friction are admissible, so a solve whose objective ends above
/// theirs did not converge (a stalled or capped solve that friction led astray); the
/// frictionless solution is kept then.
void keepNoWorseThanFrictionless(PreparedSolve& solve, Body& body, const Vec3& freeVelocity,
                                 const Vec3& freeAngularVelocity, Real freeKinetic,
                                 int iterations)
{
    const Vec3 solvedVelocity = body.linearVelocity;
    const Vec3 solvedAngularVelocity = body.angularVelocity;
    const std::array<SolverPoint, 8> solved = solve.points;
    const Real solvedObjective = restingObjective(solve, body, freeKinetic);
    body.linearVelocity = freeVelocity;
    body.angularVelocity = freeAngularVelocity;
    restartFromZero(solve);
    for (int i = 0; i < solve.count; ++i) {
        solve.points[i].friction = 0.0;
    }
    solvePoints(body, solve.frame, std::span(solve.points.data(), solve.count), 1.0, iterations,
                kRestingConvergence, false);
    const Real frictionlessObjective = restingObjective(solve, body, freeKinetic);
    if (solvedObjective <= frictionlessObjective + 1e-12 * freeKinetic) {
        body.linearVelocity = solvedVelocity;
        body.angularVelocity = solvedAngularVelocity;
        solve.points = solved;
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
    const Real kineticBeforeGravity = body.kineticEnergy();
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
    const Real freeKinetic = body.kineticEnergy();
    const Real allowed = freeKinetic * (1.0 + 1e-12) + std::numeric_limits<Real>::min();
    for (int i = 0; i < solve.count; ++i) {
        SolverPoint& point = solve.points[i];
        // (5.10): start from last step's impulse rates at this vertex, inside the cone.
        const int vertex = manifold.points[i].vertex;
        if (((warmStart.vertices >> vertex) & 1u) == 0u) {
            continue;
        }
        point.normalImpulse = std::max(0.0, warmStart.normalRate[vertex] * tau);
        const Vec3 friction = warmStart.frictionRate[vertex] * tau;
        const FrictionImpulse inCone =
            scaledIntoDisc(glm::dot(friction, solve.frame.t1), glm::dot(friction, solve.frame.t2),
                           point.friction * point.normalImpulse);
        point.tangentImpulse1 = inCone.impulse1;
        point.tangentImpulse2 = inCone.impulse2;
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
    // (5.12a): more kinetic energy than before gravity acted (beyond rounding of T(0)) is
    // possible, a slide down a slope, but then the solve must do no worse on its objective
    // than the frictionless one
    if (body.kineticEnergy() > kineticBeforeGravity + 1e-12 * freeKinetic) {
        keepNoWorseThanFrictionless(solve, body, freeVelocity, freeAngularVelocity, freeKinetic,
                                    settings.iterations);
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
