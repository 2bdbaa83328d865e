// Four soft manifolds of one colour solved side by side, one per vector lane
// (docs/physics/12-soft-step.md, (12.4), (12.5), (12.9)).
#include "dynamics/soft_lanes.hpp"

#include "dynamics/four_lanes.hpp"
#include "parallel_for.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace tumble {

namespace {

using namespace lanes;

/// The k-th point of each lane's manifold, or nothing (`active` clear, the point's rows zero).
struct LanePoint {
    Wide3 anchorA, anchorB, angularA, angularB, responseA, responseB;
    Wide baseSeparation, normalMass, leverArm, normalImpulse, maxNormalImpulse, normalWork;
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
        frictionWork, invMassA, invMassB;
    Mask againstStatic, movesA, movesB;
    LanePoint points[4];
    std::array<std::uint32_t, kLanes> manifold{};
    std::array<std::uint32_t, kLanes> bodyA{};
    std::array<std::uint32_t, kLanes> bodyB{};
    std::uint32_t lanes = 0;
};

void packPoint(LanePoint& p, int lane, const SoftPoint& from)
{
    lanes::setLane(p.anchorA, lane, from.anchorA);
    lanes::setLane(p.anchorB, lane, from.anchorB);
    lanes::setLane(p.angularA, lane, from.angularA);
    lanes::setLane(p.angularB, lane, from.angularB);
    lanes::setLane(p.responseA, lane, from.responseA);
    lanes::setLane(p.responseB, lane, from.responseB);
    p.baseSeparation[lane] = from.baseSeparation;
    p.normalMass[lane] = from.normalMass;
    p.leverArm[lane] = from.leverArm;
    p.normalImpulse[lane] = from.normalImpulse;
    p.maxNormalImpulse[lane] = from.maxNormalImpulse;
    p.normalWork[lane] = from.normalWork;
    p.active[lane] = -1;
}

void packLane(LaneBlock& block, int lane, const SoftManifold& m, std::span<const SoftBody> bodies)
{
    lanes::setLane(block.normal, lane, m.normal);
    lanes::setLane(block.tangent1, lane, m.tangent1);
    lanes::setLane(block.tangent2, lane, m.tangent2);
    lanes::setLane(block.angularA1, lane, m.angularA1);
    lanes::setLane(block.angularA2, lane, m.angularA2);
    lanes::setLane(block.angularB1, lane, m.angularB1);
    lanes::setLane(block.angularB2, lane, m.angularB2);
    lanes::setLane(block.responseA1, lane, m.responseA1);
    lanes::setLane(block.responseA2, lane, m.responseA2);
    lanes::setLane(block.responseB1, lane, m.responseB1);
    lanes::setLane(block.responseB2, lane, m.responseB2);
    lanes::setLane(block.twistResponseA, lane, m.twistResponseA);
    lanes::setLane(block.twistResponseB, lane, m.twistResponseB);
    for (int i = 0; i < 3; ++i) {
        block.tangentK[i][lane] = m.tangentK[i];
        block.tangentMass[i][lane] = m.tangentMass[i];
    }
    block.twistK[lane] = m.twistK;
    block.twistMass[lane] = m.twistMass;
    block.friction[lane] = m.friction;
    block.frictionImpulse1[lane] = m.frictionImpulse1;
    block.frictionImpulse2[lane] = m.frictionImpulse2;
    block.twistImpulse[lane] = m.twistImpulse;
    block.frictionWork[lane] = m.frictionWork;
    block.invMassA[lane] = bodies[m.bodyA].invMass;
    block.invMassB[lane] = bodies[m.bodyB].invMass;
    block.againstStatic[lane] = m.againstStatic ? -1 : 0;
    block.movesA[lane] = bodies[m.bodyA].invMass > 0.0 ? -1 : 0;
    block.movesB[lane] = bodies[m.bodyB].invMass > 0.0 ? -1 : 0;
    for (int k = 0; k < m.pointCount; ++k) {
        packPoint(block.points[k], lane, m.points[k]);
    }
}

/// An empty block: every lane the static body's, every row zero; an absent point has a unit
/// mass so that nothing divides by zero.
LaneBlock emptyBlock(std::uint32_t staticIndex)
{
    LaneBlock block{};
    block.bodyA.fill(staticIndex);
    block.bodyB.fill(staticIndex);
    for (LanePoint& p : block.points) {
        p.normalMass = splat(1.0);
    }
    return block;
}

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

/// a -= s d (or a += s d with `add`): SoftPair's updates, lane by lane.
TUMBLE_WIDE_INLINE void addScaled(Wide3& a, Wide s, const Wide3& d, bool add)
{
    a = add ? Wide3{a.x + s * d.x, a.y + s * d.y, a.z + s * d.z}
            : Wide3{a.x - s * d.x, a.y - s * d.y, a.z - s * d.z};
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

/// solveSoft over blocks. On x86-64 with GCC it is compiled for AVX2 and for the baseline, and
/// the loader picks the one the processor runs; both give the same bits (no fused operations).
TUMBLE_WIDE_CLONES
void solveBlocks(std::span<LaneBlock> blocks, std::span<SoftBody> bodies, const LaneSettings& s)
{
    for (LaneBlock& block : blocks) {
        LaneVelocities v = gather(block, bodies);
        const LaneMotion motion = motionOf(block, bodies);
        // (12.4): forth and back over the points
        for (int k = 0; k < 4; ++k) {
            solveNormal(block, block.points[k], motion, s, v);
        }
        for (int k = 3; k >= 0; --k) {
            solveNormal(block, block.points[k], motion, s, v);
        }
        if (!s.useBias) {
            solveFriction(block, v);
        }
        scatter(block, v, bodies);
    }
}

/// warmStartSoft over blocks, compiled as solveBlocks is.
TUMBLE_WIDE_CLONES
void warmStartBlocks(std::span<const LaneBlock> blocks, std::span<SoftBody> bodies)
{
    for (const LaneBlock& block : blocks) {
        LaneVelocities v = gather(block, bodies);
        for (const LanePoint& p : block.points) {
            applyNormal(block, p, p.normalImpulse, p.active, v);
        }
        applyTwist(block, block.twistImpulse, v);
        applyFriction(block, block.frictionImpulse1, block.frictionImpulse2, v);
        scatter(block, v, bodies);
    }
}

/// Blocks handed to a thread at a time in a large colour.
constexpr std::size_t kBlocksPerShare = 8;
/// A colour of fewer manifolds than this is swept by one thread. In lanes a manifold costs a
/// quarter of what it costs alone, yet a colour of 64 still takes several times what handing
/// out its two shares does.
constexpr std::size_t kThreadedLaneManifolds = 64;

/// Calls `visit(first, last)` over a colour's blocks [begin, end): in shares over `threads` for a
/// colour of kThreadedLaneManifolds or more, else at once.
template <typename Visit>
void forEachShare(std::size_t begin, std::size_t end, std::size_t manifolds, int threads,
                  const Visit& visit)
{
    if (manifolds < kThreadedLaneManifolds || threads < 2) {
        visit(begin, end);
        return;
    }
    const std::size_t shares = (end - begin + kBlocksPerShare - 1) / kBlocksPerShare;
    parallelFor(shares, threads, [&](std::size_t share) {
        const std::size_t first = begin + share * kBlocksPerShare;
        visit(first, std::min(end, first + kBlocksPerShare));
    });
}

} // namespace

struct SoftLanes::Storage {
    std::vector<LaneBlock> blocks;
    /// Colour c's blocks are [colourBlocks[c], colourBlocks[c + 1]); its manifold count.
    std::vector<std::size_t> colourBlocks;
    std::vector<std::size_t> colourManifolds;
    std::vector<std::uint32_t> firstManifold;
    std::vector<std::uint32_t> laneCount;
};

SoftLanes::SoftLanes() : m_storage(std::make_unique<Storage>()) {}

SoftLanes::~SoftLanes() = default;

void SoftLanes::pack(std::span<const SoftManifold> manifolds, const SoftColours& colours,
                     std::span<const SoftBody> bodies, int threads)
{
    Storage& storage = *m_storage;
    storage.colourBlocks.assign(1, 0);
    storage.colourManifolds.clear();
    const std::size_t groups = colours.offsets.empty() ? 0 : colours.offsets.size() - 1;
    // every group but the last (the overflow) is a colour
    std::size_t blockCount = 0;
    for (std::size_t c = 0; c + 1 < groups; ++c) {
        const std::size_t size = colours.offsets[c + 1] - colours.offsets[c];
        blockCount += (size + kLanes - 1) / kLanes;
        storage.colourBlocks.push_back(blockCount);
        storage.colourManifolds.push_back(size);
    }
    const auto staticIndex = static_cast<std::uint32_t>(bodies.size() - 1);
    storage.blocks.resize(blockCount);
    // the first manifold and the lanes of each block, so that the blocks (not the colours, of
    // very unequal sizes) are shared out over the threads, each writing only itself
    storage.firstManifold.resize(blockCount);
    storage.laneCount.resize(blockCount);
    std::size_t b = 0;
    for (std::size_t c = 0; c + 1 < groups; ++c) {
        const std::size_t end = colours.offsets[c + 1];
        for (std::size_t first = colours.offsets[c]; first < end; first += kLanes, ++b) {
            storage.firstManifold[b] = static_cast<std::uint32_t>(first);
            storage.laneCount[b] =
                static_cast<std::uint32_t>(std::min<std::size_t>(kLanes, end - first));
        }
    }
    parallelFor(blockCount, threads, [&](std::size_t index) {
        LaneBlock& block = storage.blocks[index];
        block = emptyBlock(staticIndex);
        block.lanes = storage.laneCount[index];
        for (std::uint32_t lane = 0; lane < block.lanes; ++lane) {
            const std::uint32_t m = storage.firstManifold[index] + lane;
            block.manifold[lane] = m;
            block.bodyA[lane] = manifolds[m].bodyA;
            block.bodyB[lane] = manifolds[m].bodyB;
            packLane(block, static_cast<int>(lane), manifolds[m], bodies);
        }
    });
}

void SoftLanes::warmStart(std::size_t colour, std::span<SoftBody> bodies, int threads) const
{
    const Storage& storage = *m_storage;
    forEachShare(storage.colourBlocks[colour], storage.colourBlocks[colour + 1],
                 storage.colourManifolds[colour], threads,
                 [&](std::size_t first, std::size_t last) {
                     warmStartBlocks({storage.blocks.data() + first, last - first}, bodies);
                 });
}

void SoftLanes::solve(std::size_t colour, std::span<SoftBody> bodies,
                      const SoftSolveSettings& settings, bool useBias, int threads)
{
    Storage& storage = *m_storage;
    const Softness& fixed = settings.staticSoftness;
    const Softness& moving = settings.dynamicSoftness;
    const LaneSettings lanes{splat(fixed.biasRate),        splat(fixed.massScale),
                             splat(fixed.impulseScale),    splat(moving.biasRate),
                             splat(moving.massScale),      splat(moving.impulseScale),
                             splat(settings.inverseSubstep), splat(-settings.pushSpeed),
                             useBias};
    forEachShare(storage.colourBlocks[colour], storage.colourBlocks[colour + 1],
                 storage.colourManifolds[colour], threads,
                 [&](std::size_t first, std::size_t last) {
                     solveBlocks({storage.blocks.data() + first, last - first}, bodies, lanes);
                 });
}

void SoftLanes::unpack(std::span<SoftManifold> manifolds, int threads) const
{
    const Storage& storage = *m_storage;
    parallelFor(storage.blocks.size(), threads, [&](std::size_t b) {
        const LaneBlock& block = storage.blocks[b];
        for (std::uint32_t lane = 0; lane < block.lanes; ++lane) {
            SoftManifold& m = manifolds[block.manifold[lane]];
            for (int k = 0; k < m.pointCount; ++k) {
                const LanePoint& p = block.points[k];
                m.points[k].normalImpulse = p.normalImpulse[lane];
                m.points[k].maxNormalImpulse = p.maxNormalImpulse[lane];
                m.points[k].normalWork = p.normalWork[lane];
            }
            m.frictionImpulse1 = block.frictionImpulse1[lane];
            m.frictionImpulse2 = block.frictionImpulse2[lane];
            m.twistImpulse = block.twistImpulse[lane];
            m.frictionWork = block.frictionWork[lane];
        }
    });
}

} // namespace tumble
