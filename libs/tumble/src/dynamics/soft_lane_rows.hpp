// The soft step's rows four manifolds at a time: a block's layout, lane by lane, and the
// lane-by-lane forms of the one-manifold pass's operations, each in the same order so that a lane
// rounds as soft_contact_solver.cpp does (docs/physics/12-soft-step.md, (12.9)). For
// dynamics/soft_lanes.cpp only.
#pragma once

#include "dynamics/four_lanes.hpp"
#include "dynamics/soft_contact_solver.hpp"

#include <array>
#include <cstdint>
#include <span>

namespace tumble::soft_rows {

using namespace lanes;

/// The k-th point of each lane's manifold, or nothing (`active` clear, the point's rows zero).
/// Its angular rows r x n are formed from the anchors where a pass needs them (pointAngular):
/// a block is read twelve times a step, and its size is what the pass waits on.
struct LanePoint {
    Wide3 anchorA, anchorB;
    Wide baseSeparation, normalK, normalMass, leverArm, normalImpulse, maxNormalImpulse,
        normalWork, relativeVelocity;
    Mask active;
};

/// A 3x3 matrix of each lane, by glm's columns.
struct WideMat3 {
    Wide3 column[3];
};

/// glm's matrix times vector: row r is (m[0][r] v.x + m[1][r] v.y) + m[2][r] v.z.
TUMBLE_WIDE_INLINE Wide3 times(const WideMat3& m, const Wide3& v)
{
    return {m.column[0].x * v.x + m.column[1].x * v.y + m.column[2].x * v.z,
            m.column[0].y * v.x + m.column[1].y * v.y + m.column[2].y * v.z,
            m.column[0].z * v.x + m.column[1].z * v.y + m.column[2].z * v.z};
}

/// Four manifolds of one colour; a lane past `lanes` is empty: the static body on both sides,
/// every row zero.
struct LaneBlock {
    Wide3 normal, tangent1, tangent2;
    Wide3 angularA1, angularA2, angularB1, angularB2;
    Wide3 twistResponseA, twistResponseB;
    WideMat3 inertiaA, inertiaB;
    Wide normalCoupling[6];
    Wide tangentK[3];
    Wide tangentMass[3];
    Wide twistK, twistMass, friction, frictionImpulse1, frictionImpulse2, twistImpulse,
        frictionWork, invMassA, invMassB, restitution;
    Mask againstStatic, movesA, movesB;
    LanePoint points[4];
    std::array<std::uint32_t, kLanes> manifold{};
    std::array<std::uint32_t, kLanes> bodyA{};
    std::array<std::uint32_t, kLanes> bodyB{};
    std::uint32_t lanes = 0;
};

/// The velocities of each lane's two bodies, held in registers through the block.
struct LaneVelocities {
    Wide3 vA, wA, vB, wB;
};

TUMBLE_WIDE_INLINE LaneVelocities gather(const LaneBlock& block, std::span<const SoftBody> bodies)
{
    LaneVelocities v;
    for (int lane = 0; lane < kLanes; ++lane) {
        const SoftBody& a = bodies[block.bodyA[lane]];
        const SoftBody& b = bodies[block.bodyB[lane]];
        lanes::setLane(v.vA, lane, a.linearVelocity);
        lanes::setLane(v.wA, lane, a.angularVelocity);
        lanes::setLane(v.vB, lane, b.linearVelocity);
        lanes::setLane(v.wB, lane, b.angularVelocity);
    }
    return v;
}

/// Writes back the velocities of the lanes' moving bodies (the static body is never written).
TUMBLE_WIDE_INLINE void scatter(const LaneBlock& block, const LaneVelocities& v,
                                std::span<SoftBody> bodies)
{
    for (std::uint32_t lane = 0; lane < block.lanes; ++lane) {
        const auto l = static_cast<int>(lane);
        if (block.movesA[lane] != 0) {
            bodies[block.bodyA[lane]].linearVelocity = laneOf(v.vA, l);
            bodies[block.bodyA[lane]].angularVelocity = laneOf(v.wA, l);
        }
        if (block.movesB[lane] != 0) {
            bodies[block.bodyB[lane]].linearVelocity = laneOf(v.vB, l);
            bodies[block.bodyB[lane]].angularVelocity = laneOf(v.wB, l);
        }
    }
}

TUMBLE_WIDE_INLINE Wide3 minus(const Wide3& a, const Wide3& b)
{
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}

/// glm's cross, lane by lane: (a.y b.z - b.y a.z, a.z b.x - b.z a.x, a.x b.y - b.x a.y).
TUMBLE_WIDE_INLINE Wide3 cross(const Wide3& a, const Wide3& b)
{
    return {a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y};
}

/// A point's normal row's angular parts, rA x n and rB x n, as prepareSoftRows forms them.
struct LaneAngular {
    Wide3 a, b;
};

TUMBLE_WIDE_INLINE LaneAngular pointAngular(const LaneBlock& block, const LanePoint& p)
{
    return {cross(p.anchorA, block.normal), cross(p.anchorB, block.normal)};
}

/// The normal impulses of the four points at once: their sum along n, their moments through
/// the inverse inertias.
TUMBLE_WIDE_INLINE void applyNormals(const LaneBlock& block, const Wide (&impulse)[4],
                                     LaneVelocities& v)
{
    Wide total = splat(0.0);
    Wide3 momentA{splat(0.0), splat(0.0), splat(0.0)};
    Wide3 momentB = momentA;
    for (int k = 0; k < 4; ++k) {
        const LanePoint& p = block.points[k];
        const Wide share = select(p.active, impulse[k], splat(0.0));
        const LaneAngular angular = pointAngular(block, p);
        total = total + share;
        momentA = {momentA.x + share * angular.a.x, momentA.y + share * angular.a.y,
                   momentA.z + share * angular.a.z};
        momentB = {momentB.x + share * angular.b.x, momentB.y + share * angular.b.y,
                   momentB.z + share * angular.b.z};
    }
    addScaled(v.vA, block.invMassA * total, block.normal, false);
    const Wide3 turnA = times(block.inertiaA, momentA);
    v.wA = {v.wA.x - turnA.x, v.wA.y - turnA.y, v.wA.z - turnA.z};
    addScaled(v.vB, block.invMassB * total, block.normal, true);
    const Wide3 turnB = times(block.inertiaB, momentB);
    v.wB = {v.wB.x + turnB.x, v.wB.y + turnB.y, v.wB.z + turnB.z};
}

/// SoftPair::applyTwist and SoftPair::applyFriction.
TUMBLE_WIDE_INLINE void applyTwist(const LaneBlock& block, Wide twist, LaneVelocities& v)
{
    addScaled(v.wA, twist, block.twistResponseA, false);
    addScaled(v.wB, twist, block.twistResponseB, true);
}

TUMBLE_WIDE_INLINE void applyFriction(const LaneBlock& block, Wide d1, Wide d2,
                                      LaneVelocities& v)
{
    const Wide3 impulse{d1 * block.tangent1.x + d2 * block.tangent2.x,
                        d1 * block.tangent1.y + d2 * block.tangent2.y,
                        d1 * block.tangent1.z + d2 * block.tangent2.z};
    const Wide3 turnA = times(block.inertiaA, Wide3{d1 * block.angularA1.x + d2 * block.angularA2.x,
                      d1 * block.angularA1.y + d2 * block.angularA2.y,
                      d1 * block.angularA1.z + d2 * block.angularA2.z});
    const Wide3 turnB = times(block.inertiaB, Wide3{d1 * block.angularB1.x + d2 * block.angularB2.x,
                      d1 * block.angularB1.y + d2 * block.angularB2.y,
                      d1 * block.angularB1.z + d2 * block.angularB2.z});
    addScaled(v.vA, block.invMassA, impulse, false);
    v.wA = minus(v.wA, turnA);
    addScaled(v.vB, block.invMassB, impulse, true);
    v.wB = {v.wB.x + turnB.x, v.wB.y + turnB.y, v.wB.z + turnB.z};
}

/// SoftMotion of each lane: how its bodies moved since the step began, seen along its normal.
struct LaneMotion {
    Wide centres;
    Wide3 normalA, normalB;
};

TUMBLE_WIDE_INLINE LaneMotion motionOf(const LaneBlock& block, std::span<const SoftBody> bodies)
{
    LaneMotion motion;
    for (int lane = 0; lane < kLanes; ++lane) {
        const SoftBody& a = bodies[block.bodyA[lane]];
        const SoftBody& b = bodies[block.bodyB[lane]];
        const Vec3 normal = laneOf(block.normal, lane);
        motion.centres[lane] = glm::dot(normal, b.deltaPosition - a.deltaPosition);
        lanes::setLane(motion.normalA, lane, normal * a.deltaRotation);
        lanes::setLane(motion.normalB, lane, normal * b.deltaRotation);
    }
    return motion;
}

/// What solveNormal reads of the pass's settings, as lanes.
struct LaneSettings {
    Wide staticRate, staticMass, staticImpulse;
    Wide dynamicRate, dynamicMass, dynamicImpulse;
    Wide inverseSubstep, pushLimit;
    bool useBias;
};

/// The normal velocities of the four points of each lane, n . (vB - vA) + (rB x n) . wB -
/// (rA x n) . wA, as SoftPair::normalVelocity forms them.
struct LaneNormalVelocities {
    Wide at[4];
};

TUMBLE_WIDE_INLINE LaneNormalVelocities normalVelocities(const LaneBlock& block,
                                                         const LaneVelocities& v)
{
    LaneNormalVelocities u;
    for (int k = 0; k < 4; ++k) {
        const LaneAngular angular = pointAngular(block, block.points[k]);
        u.at[k] = dot(block.normal, minus(v.vB, v.vA)) + dot(angular.b, v.wB) -
                  dot(angular.a, v.wA);
    }
    return u;
}

/// The softness of each lane's rows in one pass, against the static body or another body.
struct LaneSoftness {
    Wide massRate, mass, impulse;
};

TUMBLE_WIDE_INLINE LaneSoftness softnessOf(const LaneBlock& block, const LaneSettings& s)
{
    const Wide rate = select(block.againstStatic, s.staticRate, s.dynamicRate);
    const Wide mass = select(block.againstStatic, s.staticMass, s.dynamicMass);
    return {mass * rate, mass, select(block.againstStatic, s.staticImpulse, s.dynamicImpulse)};
}

/// What a point's normal row aims at in this pass: the gap's target speed and the soft scales,
/// the first half of solveNormal (soft_contact_solver.cpp) lane by lane, the same operations in
/// the same order. The gap is the same on the way forth and back, so it is found once a pass.
struct LaneTarget {
    Wide bias, massScale, impulseScale;
};

TUMBLE_WIDE_INLINE LaneTarget targetOf(const LanePoint& p, const LaneMotion& motion,
                                       const LaneSoftness& soft, const LaneSettings& s)
{
    const Wide gap = motion.centres + dot(motion.normalB, p.anchorB) -
                     dot(motion.normalA, p.anchorA) + p.baseSeparation;
    const Mask speculative = less(splat(0.0), gap);
    const Mask biased = s.useBias ? ~speculative : Mask{};
    const Wide softBias = maximum(soft.massRate * gap, s.pushLimit);
    return {select(speculative, gap * s.inverseSubstep, select(biased, softBias, splat(0.0))),
            select(biased, soft.mass, splat(1.0)), select(biased, soft.impulse, splat(0.0))};
}

/// The rest of solveNormal for point k lane by lane, the same operations in the same order: a
/// lane whose manifold has no point k changes nothing.
TUMBLE_WIDE_INLINE void solveNormal(LaneBlock& block, int k, const LaneTarget& t,
                                    LaneNormalVelocities& u)
{
    LanePoint& p = block.points[k];
    const Wide normalBefore = u.at[k];
    const Wide impulse = -p.normalMass * (t.massScale * normalBefore + t.bias) -
                         t.impulseScale * p.normalImpulse;
    const Wide accumulated = maximum(p.normalImpulse + impulse, splat(0.0));
    const Wide applied = accumulated - p.normalImpulse;
    const Mask active = p.active;
#pragma GCC unroll 4
    for (int i = 0; i < 4; ++i) {
        const Wide coupling = i == k ? p.normalK : block.normalCoupling[couplingIndex(i, k)];
        u.at[i] = select(active, u.at[i] + coupling * applied, u.at[i]);
    }
    const Wide work = applied * (normalBefore + splat(0.5) * applied / p.normalMass);
    p.normalImpulse = select(active, accumulated, p.normalImpulse);
    p.maxNormalImpulse = select(active, maximum(p.maxNormalImpulse, applied), p.maxNormalImpulse);
    p.normalWork = select(active, p.normalWork + work, p.normalWork);
}

/// solveFriction (soft_contact_solver.cpp) lane by lane, the same operations in the same order.
TUMBLE_WIDE_INLINE void solveFriction(LaneBlock& block, LaneVelocities& v)
{
    Wide load = splat(0.0);
    Wide twistLimit = splat(0.0);
    for (const LanePoint& p : block.points) {
        load = select(p.active, load + p.normalImpulse, load);
        twistLimit = select(p.active, twistLimit + p.leverArm * p.normalImpulse, twistLimit);
    }
    twistLimit = twistLimit * block.friction;
    const Wide spin = dot(block.normal, minus(v.wB, v.wA));
    const Wide free = block.twistImpulse - block.twistMass * spin;
    const Wide low = -twistLimit;
    const Wide twist = select(less(free, low), low, select(less(twistLimit, free), twistLimit, free));
    const Wide twistApplied = twist - block.twistImpulse;
    block.twistImpulse = twist;
    applyTwist(block, twistApplied, v);
    block.frictionWork =
        block.frictionWork + twistApplied * (spin + splat(0.5) * block.twistK * twistApplied);

    const Wide slip1 = dot(block.tangent1, minus(v.vB, v.vA)) + dot(block.angularB1, v.wB) -
                       dot(block.angularA1, v.wA);
    const Wide slip2 = dot(block.tangent2, minus(v.vB, v.vA)) + dot(block.angularB2, v.wB) -
                       dot(block.angularA2, v.wA);
    const Wide(&mt)[3] = block.tangentMass;
    Wide next1 = block.frictionImpulse1 - (mt[0] * slip1 + mt[1] * slip2);
    Wide next2 = block.frictionImpulse2 - (mt[1] * slip1 + mt[2] * slip2);
    const Wide limit = block.friction * load;
    const Wide size = squareRoot(next1 * next1 + next2 * next2);
    const Mask outside = less(limit, size);
    const Wide shrink = select(less(splat(0.0), size), limit / size, splat(0.0));
    next1 = select(outside, next1 * shrink, next1);
    next2 = select(outside, next2 * shrink, next2);
    const Wide d1 = next1 - block.frictionImpulse1;
    const Wide d2 = next2 - block.frictionImpulse2;
    block.frictionImpulse1 = next1;
    block.frictionImpulse2 = next2;
    applyFriction(block, d1, d2, v);
    const Wide(&kt)[3] = block.tangentK;
    const Wide change1 = kt[0] * d1 + kt[1] * d2;
    const Wide change2 = kt[1] * d1 + kt[2] * d2;
    block.frictionWork = block.frictionWork + (d1 * (slip1 + splat(0.5) * change1) +
                                               d2 * (slip2 + splat(0.5) * change2));
}

} // namespace tumble::soft_rows
