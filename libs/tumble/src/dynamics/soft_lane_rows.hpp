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
struct LanePoint {
    Wide3 anchorA, anchorB, angularA, angularB, responseA, responseB;
    Wide baseSeparation, normalMass, leverArm, normalImpulse, maxNormalImpulse, normalWork,
        relativeVelocity;
    Mask active;
};

/// Four manifolds of one colour; a lane past `lanes` is empty: the static body on both sides,
/// every row zero.
struct LaneBlock {
    Wide3 normal, tangent1, tangent2;
    Wide3 angularA1, angularA2, angularB1, angularB2;
    Wide3 responseA1, responseA2, responseB1, responseB2, twistResponseA, twistResponseB;
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

/// SoftPair::applyNormal where `active`.
TUMBLE_WIDE_INLINE void applyNormal(const LaneBlock& block, const LanePoint& p, Wide impulse,
                                    Mask active, LaneVelocities& v)
{
    pushAlong(v.vA, block.invMassA * impulse, block.normal, active, false);
    pushAlong(v.wA, impulse, p.responseA, active, false);
    pushAlong(v.vB, block.invMassB * impulse, block.normal, active, true);
    pushAlong(v.wB, impulse, p.responseB, active, true);
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
    const Wide3 turnA{d1 * block.responseA1.x + d2 * block.responseA2.x,
                      d1 * block.responseA1.y + d2 * block.responseA2.y,
                      d1 * block.responseA1.z + d2 * block.responseA2.z};
    const Wide3 turnB{d1 * block.responseB1.x + d2 * block.responseB2.x,
                      d1 * block.responseB1.y + d2 * block.responseB2.y,
                      d1 * block.responseB1.z + d2 * block.responseB2.z};
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

/// solveNormal (soft_contact_solver.cpp) lane by lane, the same operations in the same order.
TUMBLE_WIDE_INLINE void solveNormal(const LaneBlock& block, LanePoint& p, const LaneMotion& motion,
                                    const LaneSettings& s, LaneVelocities& v)
{
    const Wide gap = motion.centres + dot(motion.normalB, p.anchorB) -
                     dot(motion.normalA, p.anchorA) + p.baseSeparation;
    const Mask speculative = less(splat(0.0), gap);
    const Mask biased = s.useBias ? ~speculative : Mask{};
    const Wide rate = select(block.againstStatic, s.staticRate, s.dynamicRate);
    const Wide softMass = select(block.againstStatic, s.staticMass, s.dynamicMass);
    const Wide softImpulse = select(block.againstStatic, s.staticImpulse, s.dynamicImpulse);
    const Wide softBias = maximum(softMass * rate * gap, s.pushLimit);
    const Wide bias =
        select(speculative, gap * s.inverseSubstep, select(biased, softBias, splat(0.0)));
    const Wide massScale = select(biased, softMass, splat(1.0));
    const Wide impulseScale = select(biased, softImpulse, splat(0.0));
    const Wide normalBefore = dot(block.normal, minus(v.vB, v.vA)) + dot(p.angularB, v.wB) -
                              dot(p.angularA, v.wA);
    const Wide impulse = -p.normalMass * (massScale * normalBefore + bias) -
                         impulseScale * p.normalImpulse;
    const Wide accumulated = maximum(p.normalImpulse + impulse, splat(0.0));
    const Wide applied = accumulated - p.normalImpulse;
    const Mask active = p.active;
    applyNormal(block, p, applied, active, v);
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
