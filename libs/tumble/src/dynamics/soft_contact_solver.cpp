// Soft contact rows (docs/physics/12-soft-step.md, (12.2)-(12.6)).
#include "dynamics/soft_contact_solver.hpp"

#include "dynamics/soft_lanes.hpp"
#include "dynamics/soft_pair.hpp"
#include "parallel_for.hpp"

#include <algorithm>
#include <cmath>

namespace tumble {

namespace {

/// Sweeps forth and back over a bouncing manifold's points (12.6).
constexpr int kRestitutionSweeps = 4;
/// Calls `visit(i)` for every manifold in colour order: each colour's manifolds move no dynamic
/// body twice, so a large colour is split over `threads` and the result is the same for any
/// count (11.5c); the overflow group goes in order on one thread. With `lanes`, the colours are
/// handed to `inLanes()` instead, and `visit(i)` is given the overflow's i-th manifold.
template <typename Visit, typename InLanes>
void forEachManifold(std::size_t count, const SoftColours& colours, int threads,
                     const Visit& visit, const SoftLanes* lanes, const InLanes& inLanes)
{
    if (colours.offsets.size() < 2) {
        for (std::size_t i = 0; i < count; ++i) {
            visit(i);
        }
        return;
    }
    const std::size_t groups = colours.offsets.size() - 1;
    const std::size_t base = lanes != nullptr ? colours.offsets[groups - 1] : 0;
    if (lanes != nullptr) {
        inLanes();
    }
    for (std::size_t c = lanes != nullptr ? groups - 1 : 0; c < groups; ++c) {
        const std::size_t first = colours.offsets[c];
        const std::size_t size = colours.offsets[c + 1] - first;
        const bool overflow = c + 1 == groups;
        const int used = !overflow && size >= kThreadedColourManifolds ? threads : 1;
        parallelFor(size, used, [&](std::size_t i) { visit(first - base + i); });
    }
}

/// (12.4): the normal row of point k, soft and biased or (the relax pass) rigid, from and into
/// the normal velocities `u` of the manifold's points: its impulse changes u_i by K_ik times it.
void solveNormal(const SoftManifold& m, int k, SoftPoint& p, const SoftMotion& motion,
                 const SoftSolveSettings& settings, bool useBias, std::array<Real, 4>& u)
{
    // the gap now, from how far the bodies moved and turned since the step began (12.3)
    const Real gap = motion.centres + glm::dot(motion.normalB, p.anchorB) -
                     glm::dot(motion.normalA, p.anchorA) + p.baseSeparation;
    Real bias = 0.0;
    Real massScale = 1.0;
    Real impulseScale = 0.0;
    if (gap > 0.0) {
        // speculative: the point may close its gap within the sub-step, no more
        bias = gap * settings.inverseSubstep;
    } else if (useBias) {
        const Softness& soft = m.againstStatic ? settings.staticSoftness : settings.dynamicSoftness;
        bias = std::max(soft.massScale * soft.biasRate * gap, -settings.pushSpeed);
        massScale = soft.massScale;
        impulseScale = soft.impulseScale;
    }
    const Real normalBefore = u[k];
    const Real impulse =
        -p.normalMass * (massScale * normalBefore + bias) - impulseScale * p.normalImpulse;
    const Real accumulated = std::max(p.normalImpulse + impulse, 0.0);
    const Real applied = accumulated - p.normalImpulse;
    p.normalImpulse = accumulated;
    p.maxNormalImpulse = std::max(p.maxNormalImpulse, applied);
    for (int i = 0; i < m.pointCount; ++i) {
        const Real coupling = i == k ? p.normalK : m.normalCoupling[couplingIndex(i, k)];
        u[i] = u[i] + coupling * applied;
    }
    // (8.2): the work of an impulse is its size times the mean of the velocities it joins
    p.normalWork += applied * (normalBefore + 0.5 * applied / p.normalMass);
}

/// (12.5): the twist about the normal, bounded by mu sum |r_i| lambda_i, then the sliding at the
/// centre, its impulse brought back onto the disc of radius mu sum lambda_i.
void solveFriction(SoftPair& pair, SoftManifold& m)
{
    Real load = 0.0;
    Real twistLimit = 0.0;
    for (int k = 0; k < m.pointCount; ++k) {
        load += m.points[k].normalImpulse;
        twistLimit += m.points[k].leverArm * m.points[k].normalImpulse;
    }
    twistLimit *= m.friction;
    const Real spin = glm::dot(m.normal, pair.wB - pair.wA);
    const Real twist =
        std::clamp(m.twistImpulse - m.twistMass * spin, -twistLimit, twistLimit);
    const Real twistApplied = twist - m.twistImpulse;
    m.twistImpulse = twist;
    pair.applyTwist(m, twistApplied);
    m.frictionWork += twistApplied * (spin + 0.5 * m.twistK * twistApplied);

    const Vec3 sliding = pair.centreVelocity(m);
    const Real slip1 = glm::dot(m.tangent1, sliding);
    const Real slip2 = glm::dot(m.tangent2, sliding);
    const auto& mt = m.tangentMass;
    Real next1 = m.frictionImpulse1 - (mt[0] * slip1 + mt[1] * slip2);
    Real next2 = m.frictionImpulse2 - (mt[1] * slip1 + mt[2] * slip2);
    const Real limit = m.friction * load;
    const Real size = std::sqrt(next1 * next1 + next2 * next2);
    if (size > limit) {
        const Real shrink = size > 0.0 ? limit / size : 0.0;
        next1 *= shrink;
        next2 *= shrink;
    }
    const Real d1 = next1 - m.frictionImpulse1;
    const Real d2 = next2 - m.frictionImpulse2;
    m.frictionImpulse1 = next1;
    m.frictionImpulse2 = next2;
    pair.applyFriction(m, d1, d2);
    const auto& kt = m.tangentK;
    const Real change1 = kt[0] * d1 + kt[1] * d2;
    const Real change2 = kt[1] * d1 + kt[2] * d2;
    m.frictionWork += d1 * (slip1 + 0.5 * change1) + d2 * (slip2 + 0.5 * change2);
}

} // namespace

void warmStartSoft(std::span<SoftManifold> manifolds, std::span<SoftBody> bodies,
                   const SoftColours& colours, int threads, SoftLanes* lanes)
{
    const auto inLanes = [&] { lanes->warmStart(bodies, threads); };
    forEachManifold(manifolds.size(), colours, threads, [&](std::size_t index) {
        SoftManifold& m = manifolds[index];
        SoftPair pair(bodies[m.bodyA], bodies[m.bodyB]);
        std::array<Real, 4> impulses{};
        for (int k = 0; k < m.pointCount; ++k) {
            impulses[k] = m.points[k].normalImpulse;
        }
        const SoftPair::RowVelocities before = pair.rowVelocities(m);
        pair.applyAccumulated(m, impulses, m.twistImpulse, m.frictionImpulse1,
                              m.frictionImpulse2);
        const SoftPair::RowVelocities after = pair.rowVelocities(m);
        // (8.2), (12.8): impulses applied at once do the work of each row's impulse times the
        // mean of its velocity before and after; the rows' sum is the bodies' kinetic change
        for (int k = 0; k < m.pointCount; ++k) {
            SoftPoint& p = m.points[k];
            p.normalWork += p.normalImpulse * (0.5 * (before.normal[k] + after.normal[k]));
        }
        m.frictionWork += m.twistImpulse * (0.5 * (before.spin + after.spin)) +
                          (m.frictionImpulse1 * (0.5 * (before.slip1 + after.slip1)) +
                           m.frictionImpulse2 * (0.5 * (before.slip2 + after.slip2)));
        pair.store();
    }, lanes, inLanes);
}

void solveSoft(std::span<SoftManifold> manifolds, std::span<SoftBody> bodies,
               const SoftSolveSettings& settings, bool useBias, const SoftColours& colours,
               int threads, SoftLanes* lanes)
{
    const auto inLanes = [&] { lanes->solve(bodies, settings, useBias, threads); };
    forEachManifold(manifolds.size(), colours, threads, [&](std::size_t index) {
        SoftManifold& m = manifolds[index];
        SoftPair pair(bodies[m.bodyA], bodies[m.bodyB]);
        const SoftMotion motion(m, pair.a, pair.b);
        std::array<Real, 4> u = pair.normalVelocities(m);
        std::array<Real, 4> before{};
        for (int k = 0; k < m.pointCount; ++k) {
            before[k] = m.points[k].normalImpulse;
        }
        // (12.4): forth and back over the points, so that a face's impulses carry no bias of
        // the order in which its points come; the bodies take what the sweeps added at the end
        for (int k = 0; k < m.pointCount; ++k) {
            solveNormal(m, k, m.points[k], motion, settings, useBias, u);
        }
        for (int k = m.pointCount - 1; k >= 0; --k) {
            solveNormal(m, k, m.points[k], motion, settings, useBias, u);
        }
        std::array<Real, 4> added{};
        for (int k = 0; k < m.pointCount; ++k) {
            added[k] = m.points[k].normalImpulse - before[k];
        }
        pair.applyNormals(m, added);
        // (12.5): friction in both passes, so that the positions the biased pass moves to
        // are not reached sliding
        solveFriction(pair, m);
        pair.store();
    }, lanes, inLanes);
}

void restituteManifold(SoftManifold& m, std::span<SoftBody> bodies, Real threshold)
{
    const auto bouncing = [&](const SoftPoint& p) {
        return bounces(p.relativeVelocity, p.maxNormalImpulse, threshold);
    };
    if (std::none_of(m.points.begin(), m.points.begin() + m.pointCount, bouncing)) {
        return;
    }
    SoftPair pair(bodies[m.bodyA], bodies[m.bodyB]);
    const auto restitute = [&](SoftPoint& p) {
        if (!bouncing(p)) {
            return;
        }
        const Real normalBefore = pair.normalVelocity(m.normal, p);
        const Real impulse = -p.normalMass * (normalBefore + m.restitution * p.relativeVelocity);
        const Real accumulated = std::max(p.normalImpulse + impulse, 0.0);
        const Real applied = accumulated - p.normalImpulse;
        p.normalImpulse = accumulated;
        pair.applyNormal(m.normal, p, applied);
        p.normalWork += applied * (normalBefore + 0.5 * applied / p.normalMass);
    };
    // (12.6): a few sweeps forth and back over the manifold's points, so that a face that lands
    // flat leaves flat
    for (int sweep = 0; sweep < kRestitutionSweeps; ++sweep) {
        for (int k = 0; k < m.pointCount; ++k) {
            restitute(m.points[k]);
        }
        for (int k = m.pointCount - 1; k >= 0; --k) {
            restitute(m.points[k]);
        }
    }
    pair.store();
}

void restituteSoft(std::span<SoftManifold> manifolds, std::span<SoftBody> bodies, Real threshold,
                   const SoftColours& colours, int threads, SoftLanes* lanes)
{
    const auto inLanes = [&] { lanes->restitute(bodies, threshold, threads); };
    forEachManifold(manifolds.size(), colours, threads, [&](std::size_t index) {
        if (manifolds[index].restitution != 0.0) {
            restituteManifold(manifolds[index], bodies, threshold);
        }
    }, lanes, inLanes);
}

SoftContactResult softResultOf(const SoftManifold& m)
{
    SoftContactResult result;
    result.pointCount = m.pointCount;
    for (int k = 0; k < m.pointCount; ++k) {
        result.normalImpulses[k] = m.points[k].normalImpulse;
        result.normalWork[k] = m.points[k].normalWork;
    }
    result.frictionImpulse = m.frictionImpulse1 * m.tangent1 + m.frictionImpulse2 * m.tangent2;
    result.twistImpulse = m.twistImpulse;
    result.frictionWork = m.frictionWork;
    return result;
}

void restartSoftManifold(SoftManifold& manifold, std::span<const SoftBody> bodies,
                         Real staticFriction, Real kineticFriction)
{
    const SoftBody& a = bodies[manifold.bodyA];
    const SoftBody& b = bodies[manifold.bodyB];
    for (int k = 0; k < manifold.pointCount; ++k) {
        SoftPoint& p = manifold.points[k];
        p.relativeVelocity =
            glm::dot(manifold.normal, relativeVelocityAt(a, b, p.anchorA, p.anchorB));
        p.maxNormalImpulse = 0.0;
        p.normalWork = 0.0;
    }
    manifold.frictionWork = 0.0;
    manifold.friction =
        frictionAtCentre(relativeVelocityAt(a, b, manifold.centreA, manifold.centreB),
                         manifold.normal, staticFriction, kineticFriction);
}

} // namespace tumble
