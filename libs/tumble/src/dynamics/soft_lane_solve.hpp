// The soft step's passes over a block of manifolds at a time: each point's normal row from the
// points' normal velocities (12.4a), the twist and friction rows, lane by lane in the order of
// soft_contact_solver.cpp (docs/physics/12-soft-step.md, (12.4), (12.5), (12.9)). For
// dynamics/soft_lanes.cpp only.
#pragma once

#include "dynamics/soft_lane_rows.hpp"

namespace tumble::soft_rows {

/// SoftMotion of each lane: how its bodies moved since the step began, seen along its normal.
struct LaneMotion {
    Wide centres;
    Wide3 normalA, normalB;
};

#if TUMBLE_TRANSPOSE_BY_SHUFFLES
/// A body's displacement and the first entry of its rotation since the step began start one row
/// of eight doubles, the rest of the rotation fills the next (lane_transpose.hpp).
static_assert(offsetof(SoftBody, deltaRotation) == offsetof(SoftBody, deltaPosition) + 56 &&
              sizeof(SoftBody) >= offsetof(SoftBody, deltaPosition) + 128);

/// One side's displacements and rotations since the step began, turned into the lanes' columns:
/// `moved` the displacement, `turn[j]` the entry j of the rotation in glm's column order.
TUMBLE_WIDE_INLINE void gatherMotion(const std::array<std::uint32_t, kLanes>& index,
                                     std::span<const SoftBody> bodies, Wide3& moved,
                                     Wide (&turn)[9])
{
    Wide first[8];
    Wide second[8];
    for (int lane = 0; lane < kLanes; ++lane) {
        const auto* row = reinterpret_cast<const char*>(&bodies[index[lane]].deltaPosition);
        std::memcpy(&first[lane], row, sizeof(Wide));
        std::memcpy(&second[lane], row + sizeof(Wide), sizeof(Wide));
    }
    transposeEight(first);
    transposeEight(second);
    moved = {first[0], first[1], first[2]};
    turn[0] = first[7];
    for (int j = 1; j < 9; ++j) {
        turn[j] = second[j - 1];
    }
}

/// glm's row vector times matrix, n R: entry c is (R[c][0] n.x + R[c][1] n.y) + R[c][2] n.z.
TUMBLE_WIDE_INLINE Wide3 timesRotation(const Wide3& n, const Wide (&turn)[9])
{
    return {turn[0] * n.x + turn[1] * n.y + turn[2] * n.z,
            turn[3] * n.x + turn[4] * n.y + turn[5] * n.z,
            turn[6] * n.x + turn[7] * n.y + turn[8] * n.z};
}

/// motionOf with each body's rows loaded whole and turned into the lanes' columns: the same
/// operations on each lane.
TUMBLE_WIDE_INLINE LaneMotion motionOf(const LaneBlock& block, std::span<const SoftBody> bodies)
{
    Wide3 movedA, movedB;
    Wide turnA[9], turnB[9];
    gatherMotion(block.bodyA, bodies, movedA, turnA);
    gatherMotion(block.bodyB, bodies, movedB, turnB);
    return {dot(block.normal, minus(movedB, movedA)), timesRotation(block.normal, turnA),
            timesRotation(block.normal, turnB)};
}
#else
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
#endif

/// What solveNormal reads of the pass's settings, as lanes.
struct LaneSettings {
    Wide staticRate, staticMass, staticImpulse;
    Wide dynamicRate, dynamicMass, dynamicImpulse;
    Wide inverseSubstep, pushLimit;
    bool useBias;
};

/// The normal velocities of the four points of each lane, n . (vB - vA) + rB . (n x wB) -
/// rA . (n x wA), as SoftPair::normalVelocities forms them (12.4b).
struct LaneNormalVelocities {
    Wide at[4];
};

TUMBLE_WIDE_INLINE LaneNormalVelocities normalVelocities(const LaneBlock& block,
                                                         const LaneVelocities& v)
{
    const Wide along = dot(block.normal, minus(v.vB, v.vA));
    const Wide3 turnA = cross(block.normal, v.wA);
    const Wide3 turnB = cross(block.normal, v.wB);
    LaneNormalVelocities u;
    for (int k = 0; k < 4; ++k) {
        const LanePoint& p = block.points[k];
        u.at[k] = along + dot(p.anchorB, turnB) - dot(p.anchorA, turnA);
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
template <bool EveryPoint>
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
        u.at[i] = whereActive<EveryPoint>(active, u.at[i] + coupling * applied, u.at[i]);
    }
    const Wide work = applied * (normalBefore + splat(0.5) * applied / p.normalMass);
    p.normalImpulse = whereActive<EveryPoint>(active, accumulated, p.normalImpulse);
    p.maxNormalImpulse = whereActive<EveryPoint>(active, maximum(p.maxNormalImpulse, applied),
                                                 p.maxNormalImpulse);
    p.normalWork = whereActive<EveryPoint>(active, p.normalWork + work, p.normalWork);
}

/// solveFriction (soft_contact_solver.cpp) lane by lane, the same operations in the same order.
template <bool EveryPoint>
TUMBLE_WIDE_INLINE void solveFriction(LaneBlock& block, LaneVelocities& v)
{
    Wide load = splat(0.0);
    Wide twistLimit = splat(0.0);
    for (const LanePoint& p : block.points) {
        load = whereActive<EveryPoint>(p.active, load + p.normalImpulse, load);
        twistLimit = whereActive<EveryPoint>(p.active, twistLimit + p.leverArm * p.normalImpulse,
                                             twistLimit);
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

    // SoftPair::centreVelocity (12.5a)
    const Wide3 sliding = minus(plus(v.vB, cross(v.wB, block.centreB)),
                                plus(v.vA, cross(v.wA, block.centreA)));
    const Wide slip1 = dot(block.tangent1, sliding);
    const Wide slip2 = dot(block.tangent2, sliding);
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

/// SoftPair::RowVelocities of each lane, the same operations in the same order.
struct LaneRowVelocities {
    LaneNormalVelocities normal;
    Wide spin, slip1, slip2;
};

TUMBLE_WIDE_INLINE LaneRowVelocities rowVelocities(const LaneBlock& block,
                                                   const LaneVelocities& v)
{
    const Wide3 sliding = minus(plus(v.vB, cross(v.wB, block.centreB)),
                                plus(v.vA, cross(v.wA, block.centreA)));
    return {normalVelocities(block, v), dot(block.normal, minus(v.wB, v.wA)),
            dot(block.tangent1, sliding), dot(block.tangent2, sliding)};
}

/// warmStartSoft's work (soft_contact_solver.cpp, (12.8)) lane by lane: each row's impulse
/// times the mean of its velocity before and after the warm start.
template <bool EveryPoint>
TUMBLE_WIDE_INLINE void bookWarmStartWork(LaneBlock& block, const LaneRowVelocities& before,
                                          const LaneRowVelocities& after)
{
    const Wide half = splat(0.5);
    for (int k = 0; k < 4; ++k) {
        LanePoint& p = block.points[k];
        const Wide work = p.normalImpulse * (half * (before.normal.at[k] + after.normal.at[k]));
        p.normalWork = whereActive<EveryPoint>(p.active, p.normalWork + work, p.normalWork);
    }
    block.frictionWork =
        block.frictionWork +
        (block.twistImpulse * (half * (before.spin + after.spin)) +
         (block.frictionImpulse1 * (half * (before.slip1 + after.slip1)) +
          block.frictionImpulse2 * (half * (before.slip2 + after.slip2))));
}

} // namespace tumble::soft_rows
