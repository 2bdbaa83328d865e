// The soft step's rows a block of manifolds at a time: a block's layout, lane by lane, and the
// lane-by-lane forms of the one-manifold pass's impulses, each in the same order so that a lane
// rounds as soft_contact_solver.cpp does (docs/physics/12-soft-step.md, (12.9)); the passes
// themselves are in soft_lane_solve.hpp. For dynamics/soft_lane*.cpp only.
#pragma once

#include "dynamics/lane_transpose.hpp"
#include "dynamics/vector_lanes.hpp"
#include "dynamics/soft_contact_solver.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <type_traits>

namespace tumble::soft_rows {

using namespace lanes;

/// The k-th point of each lane's manifold, or nothing (`active` clear, the point's rows zero).
/// The passes work from its anchors ((12.4b): its rows r x n are not kept): a block is read
/// twelve times a step, and its size is what the pass waits on.
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

/// kLanes manifolds of one colour (vector_lanes.hpp); a lane past `lanes` is empty: the static
/// body on both sides, every row zero.
struct LaneBlock {
    Wide3 normal, tangent1, tangent2;
    /// The points' centre as offsets from each centre of mass: where friction acts (12.5a).
    Wide3 centreA, centreB;
    Wide3 twistResponseA, twistResponseB;
    WideMat3 inertiaA, inertiaB;
    Wide normalCoupling[6];
    Wide tangentK[3];
    Wide tangentMass[3];
    Wide twistK, twistMass, friction, frictionImpulse1, frictionImpulse2, twistImpulse,
        frictionWork, invMassA, invMassB, restitution;
    Mask againstStatic, movesA, movesB;
    LanePoint points[4];
    std::array<std::uint32_t, kLanes> manifold;
    std::array<std::uint32_t, kLanes> bodyA;
    std::array<std::uint32_t, kLanes> bodyB;
    std::uint32_t lanes;
    /// Whether every lane holds a manifold of four points: then every point's mask is set.
    bool everyPoint;
};
// a block is written whole by the thread that packs it (packBlock): made, it writes nothing
static_assert(std::is_trivially_default_constructible_v<LaneBlock>);

/// select(active, yes, no) for a point's mask, or `yes` where the block is known to have every
/// point (LaneBlock::everyPoint): the same lanes, without the selection.
template <bool EveryPoint>
TUMBLE_WIDE_INLINE Wide whereActive(Mask active, Wide yes, Wide no)
{
    if constexpr (EveryPoint) {
        return yes;
    } else {
        return select(active, yes, no);
    }
}

/// The velocities of each lane's two bodies, held in registers through the block.
struct LaneVelocities {
    Wide3 vA, wA, vB, wB;
};

/// A body's velocities and the first two doubles after them, the row lane_transpose.hpp turns.
static_assert(offsetof(SoftBody, angularVelocity) == offsetof(SoftBody, linearVelocity) + 24 &&
              sizeof(SoftBody) >= offsetof(SoftBody, linearVelocity) + 64);

#if TUMBLE_TRANSPOSE_BY_SHUFFLES
/// One side's velocities of the lanes: each body's row loaded whole and turned into the lanes'
/// columns.
TUMBLE_WIDE_INLINE void gatherSide(const std::array<std::uint32_t, kLanes>& index,
                                   std::span<const SoftBody> bodies, Wide3& linear, Wide3& angular)
{
    Wide rows[8];
    for (int lane = 0; lane < kLanes; ++lane) {
        std::memcpy(&rows[lane], &bodies[index[lane]].linearVelocity, sizeof(Wide));
    }
    transposeEight(rows);
    linear = {rows[0], rows[1], rows[2]};
    angular = {rows[3], rows[4], rows[5]};
}

/// Each lane's six velocities turned into a row and written over its body's, where it moves.
TUMBLE_WIDE_INLINE void scatterSide(const std::array<std::uint32_t, kLanes>& index,
                                    const Mask& moves,
                                    std::uint32_t lanes, const Wide3& linear,
                                    const Wide3& angular, std::span<SoftBody> bodies)
{
    Wide rows[8] = {linear.x, linear.y, linear.z, angular.x, angular.y, angular.z, Wide{}, Wide{}};
    transposeEight(rows);
    for (std::uint32_t lane = 0; lane < lanes; ++lane) {
        if (moves[lane] != 0) {
            std::memcpy(&bodies[index[lane]].linearVelocity, &rows[lane], 6 * sizeof(Real));
        }
    }
}
#endif

/// The velocities of each lane's bodies, lane by lane. (A pass keeps many rows in registers: the
/// shuffles of gatherByRows would spill them, so the passes use this one.)
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

/// gather, with each body's row loaded whole and turned into the lanes' columns where shuffles
/// can (the warm start, which holds little else, spends most of its time here).
TUMBLE_WIDE_INLINE LaneVelocities gatherByRows(const LaneBlock& block,
                                               std::span<const SoftBody> bodies)
{
#if TUMBLE_TRANSPOSE_BY_SHUFFLES
    LaneVelocities v;
    gatherSide(block.bodyA, bodies, v.vA, v.wA);
    gatherSide(block.bodyB, bodies, v.vB, v.wB);
    return v;
#else
    return gather(block, bodies);
#endif
}

/// scatter, each lane's velocities turned into a row and written whole where shuffles can.
TUMBLE_WIDE_INLINE void scatterByRows(const LaneBlock& block, const LaneVelocities& v,
                                      std::span<SoftBody> bodies)
{
#if TUMBLE_TRANSPOSE_BY_SHUFFLES
    scatterSide(block.bodyA, block.movesA, block.lanes, v.vA, v.wA, bodies);
    scatterSide(block.bodyB, block.movesB, block.lanes, v.vB, v.wB, bodies);
#else
    scatter(block, v, bodies);
#endif
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

/// Each lane's sums of its points' impulses, sum_k lambda_k, and of their levers, sum_k lambda_k
/// r_k on each side, as SoftPair::applyNormals forms them.
struct LaneLevers {
    Wide total;
    Wide3 a, b;
};

template <bool EveryPoint>
TUMBLE_WIDE_INLINE LaneLevers leversOf(const LaneBlock& block, const Wide (&impulse)[4])
{
    LaneLevers sums{splat(0.0), {splat(0.0), splat(0.0), splat(0.0)},
                    {splat(0.0), splat(0.0), splat(0.0)}};
    for (int k = 0; k < 4; ++k) {
        const LanePoint& p = block.points[k];
        const Wide share = whereActive<EveryPoint>(p.active, impulse[k], splat(0.0));
        sums.total = sums.total + share;
        sums.a = {sums.a.x + share * p.anchorA.x, sums.a.y + share * p.anchorA.y,
                  sums.a.z + share * p.anchorA.z};
        sums.b = {sums.b.x + share * p.anchorB.x, sums.b.y + share * p.anchorB.y,
                  sums.b.z + share * p.anchorB.z};
    }
    return sums;
}

TUMBLE_WIDE_INLINE Wide3 plus(const Wide3& a, const Wide3& b)
{
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}

/// The normal impulses of the four points at once: their sum along n, their moments
/// (sum_k lambda_k r_k) x n through the inverse inertias (12.4b).
template <bool EveryPoint>
TUMBLE_WIDE_INLINE void applyNormals(const LaneBlock& block, const Wide (&impulse)[4],
                                     LaneVelocities& v)
{
    const LaneLevers sums = leversOf<EveryPoint>(block, impulse);
    addScaled(v.vA, block.invMassA * sums.total, block.normal, false);
    v.wA = minus(v.wA, times(block.inertiaA, cross(sums.a, block.normal)));
    addScaled(v.vB, block.invMassB * sums.total, block.normal, true);
    v.wB = plus(v.wB, times(block.inertiaB, cross(sums.b, block.normal)));
}

/// SoftPair::applyTwist.
TUMBLE_WIDE_INLINE void applyTwist(const LaneBlock& block, Wide twist, LaneVelocities& v)
{
    addScaled(v.wA, twist, block.twistResponseA, false);
    addScaled(v.wB, twist, block.twistResponseB, true);
}

/// d1 t1 + d2 t2 of each lane.
TUMBLE_WIDE_INLINE Wide3 frictionImpulse(const LaneBlock& block, Wide d1, Wide d2)
{
    return {d1 * block.tangent1.x + d2 * block.tangent2.x,
            d1 * block.tangent1.y + d2 * block.tangent2.y,
            d1 * block.tangent1.z + d2 * block.tangent2.z};
}

/// SoftPair::applyFriction: P = d1 t1 + d2 t2 at the centres, its moments c x P (12.5a).
TUMBLE_WIDE_INLINE void applyFriction(const LaneBlock& block, Wide d1, Wide d2,
                                      LaneVelocities& v)
{
    const Wide3 impulse = frictionImpulse(block, d1, d2);
    addScaled(v.vA, block.invMassA, impulse, false);
    v.wA = minus(v.wA, times(block.inertiaA, cross(block.centreA, impulse)));
    addScaled(v.vB, block.invMassB, impulse, true);
    v.wB = plus(v.wB, times(block.inertiaB, cross(block.centreB, impulse)));
}

/// SoftPair::applyAccumulated: the warm start's impulses of each lane, one linear impulse and
/// one moment a body.
template <bool EveryPoint>
TUMBLE_WIDE_INLINE void applyAccumulated(const LaneBlock& block, LaneVelocities& v)
{
    const Wide impulses[4] = {block.points[0].normalImpulse, block.points[1].normalImpulse,
                              block.points[2].normalImpulse, block.points[3].normalImpulse};
    const LaneLevers sums = leversOf<EveryPoint>(block, impulses);
    const Wide3 friction = frictionImpulse(block, block.frictionImpulse1, block.frictionImpulse2);
    const Wide3 linear{sums.total * block.normal.x + friction.x,
                       sums.total * block.normal.y + friction.y,
                       sums.total * block.normal.z + friction.z};
    const Wide3 twist{block.twistImpulse * block.normal.x, block.twistImpulse * block.normal.y,
                      block.twistImpulse * block.normal.z};
    addScaled(v.vA, block.invMassA, linear, false);
    v.wA = minus(v.wA, times(block.inertiaA, plus(plus(cross(sums.a, block.normal),
                                                       cross(block.centreA, friction)),
                                                  twist)));
    addScaled(v.vB, block.invMassB, linear, true);
    v.wB = plus(v.wB, times(block.inertiaB, plus(plus(cross(sums.b, block.normal),
                                                      cross(block.centreB, friction)),
                                                 twist)));
}

} // namespace tumble::soft_rows
