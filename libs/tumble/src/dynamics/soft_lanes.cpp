// kLanes soft manifolds of one colour solved side by side, one per vector lane
// (docs/physics/12-soft-step.md, (12.4), (12.5), (12.9)).
#include "dynamics/soft_lanes.hpp"

#include "dynamics/soft_lane_prepare.hpp"
#include "dynamics/soft_lane_rows.hpp"
#include "dynamics/soft_lane_solve.hpp"
#include "dynamics/soft_lane_storage.hpp"
#include "parallel_for.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

namespace tumble {

namespace {

using namespace lanes;
using namespace soft_rows;

/// What a point brings to its lane; its rows are built in the lanes (prepareLaneRows).
void packPoint(LanePoint& p, int lane, const SoftPoint& from)
{
    lanes::setLane(p.anchorA, lane, from.anchorA);
    lanes::setLane(p.anchorB, lane, from.anchorB);
    p.baseSeparation[lane] = from.baseSeparation;
    p.normalImpulse[lane] = from.normalImpulse;
    p.maxNormalImpulse[lane] = from.maxNormalImpulse;
    p.normalWork[lane] = from.normalWork;
    p.relativeVelocity[lane] = from.relativeVelocity;
    p.active[lane] = -1;
}

/// What a manifold brings to its lane; its rows are built in the lanes (prepareLaneRows).
void packLane(LaneBlock& block, int lane, const SoftManifold& m, std::span<const SoftBody> bodies)
{
    lanes::setLane(block.normal, lane, m.normal);
    lanes::setLane(block.tangent1, lane, m.tangent1);
    lanes::setLane(block.tangent2, lane, m.tangent2);
    lanes::setLane(block.centreA, lane, m.centreA);
    lanes::setLane(block.centreB, lane, m.centreB);
    block.friction[lane] = m.friction;
    block.frictionImpulse1[lane] = m.frictionImpulse1;
    block.frictionImpulse2[lane] = m.frictionImpulse2;
    block.twistImpulse[lane] = m.twistImpulse;
    block.frictionWork[lane] = m.frictionWork;
    block.invMassA[lane] = bodies[m.bodyA].invMass;
    block.invMassB[lane] = bodies[m.bodyB].invMass;
    block.restitution[lane] = m.restitution;
    block.againstStatic[lane] = m.againstStatic ? -1 : 0;
    block.movesA[lane] = bodies[m.bodyA].invMass > 0.0 ? -1 : 0;
    block.movesB[lane] = bodies[m.bodyB].invMass > 0.0 ? -1 : 0;
    for (int k = 0; k < m.pointCount; ++k) {
        packPoint(block.points[k], lane, m.points[k]);
    }
}

static_assert(std::is_trivially_copyable_v<LaneBlock>);

/// Empties a block where it lies (a block is kilobytes: a temporary copied in costs more than
/// its fill): every lane the static body's, every row zero; an absent point has a unit mass so
/// that nothing divides by zero.
void emptyBlock(LaneBlock& block, std::uint32_t staticIndex)
{
    std::memset(static_cast<void*>(&block), 0, sizeof block);
    block.bodyA.fill(staticIndex);
    block.bodyB.fill(staticIndex);
    for (LanePoint& p : block.points) {
        p.normalMass = splat(1.0);
    }
}

/// The `lanes` manifolds from `firstManifold` (by their index in colour order) packed into
/// `block`, their rows built.
void packBlock(LaneBlock& block, std::uint32_t firstManifold, std::uint32_t lanes,
               const SoftLanes::ManifoldSource& source, std::span<const SoftBody> bodies)
{
    emptyBlock(block, static_cast<std::uint32_t>(bodies.size() - 1));
    block.lanes = lanes;
    block.everyPoint = block.lanes == kLanes;
    for (std::uint32_t lane = 0; lane < block.lanes; ++lane) {
        const std::uint32_t index = firstManifold + lane;
        const SoftManifold m = source(index);
        block.manifold[lane] = index;
        block.bodyA[lane] = m.bodyA;
        block.bodyB[lane] = m.bodyB;
        block.everyPoint = block.everyPoint && m.pointCount == 4;
        packLane(block, static_cast<int>(lane), m, bodies);
    }
    prepareLaneRows(block, bodies);
}

/// solveSoft on one block; EveryPoint where the block has every point (the same bits).
template <bool EveryPoint>
TUMBLE_WIDE_INLINE void solveBlock(LaneBlock& block, std::span<SoftBody> bodies,
                                   const LaneSettings& s)
{
    LaneVelocities v = gather(block, bodies);
    const LaneMotion motion = motionOf(block, bodies);
    LaneNormalVelocities u = normalVelocities(block, v);
    Wide before[4];
    LaneTarget targets[4];
    const LaneSoftness soft = softnessOf(block, s);
    for (int k = 0; k < 4; ++k) {
        before[k] = block.points[k].normalImpulse;
        targets[k] = targetOf(block.points[k], motion, soft, s);
    }
    // (12.4): forth and back over the points, then the bodies take what they added; unrolled,
    // so that the points' normal velocities stay in registers
#pragma GCC unroll 4
    for (int k = 0; k < 4; ++k) {
        solveNormal<EveryPoint>(block, k, targets[k], u);
    }
#pragma GCC unroll 4
    for (int k = 3; k >= 0; --k) {
        solveNormal<EveryPoint>(block, k, targets[k], u);
    }
    Wide added[4];
    for (int k = 0; k < 4; ++k) {
        added[k] = block.points[k].normalImpulse - before[k];
    }
    applyNormals<EveryPoint>(block, added, v);
    solveFriction<EveryPoint>(block, v);
    scatter(block, v, bodies);
}

/// solveSoft over blocks, built for AVX-512, AVX2 and the baseline (TUMBLE_WIDE_CLONES); all
/// give the same bits (no fused operations).
TUMBLE_WIDE_CLONES
void solveBlocks(std::span<LaneBlock> blocks, std::span<SoftBody> bodies, const LaneSettings& s)
{
    for (LaneBlock& block : blocks) {
        if (block.everyPoint) {
            solveBlock<true>(block, bodies, s);
        } else {
            solveBlock<false>(block, bodies, s);
        }
    }
}

/// warmStartSoft over blocks, compiled as solveBlocks is.
TUMBLE_WIDE_CLONES
void warmStartBlocks(std::span<LaneBlock> blocks, std::span<SoftBody> bodies)
{
    for (LaneBlock& block : blocks) {
        LaneVelocities v = gatherByRows(block, bodies);
        const LaneRowVelocities before = rowVelocities(block, v);
        if (block.everyPoint) {
            applyAccumulated<true>(block, v);
            bookWarmStartWork<true>(block, before, rowVelocities(block, v));
        } else {
            applyAccumulated<false>(block, v);
            bookWarmStartWork<false>(block, before, rowVelocities(block, v));
        }
        scatterByRows(block, v, bodies);
    }
}

/// restartSoftManifold on each lane of `block`, the same arithmetic.
void restartBlock(LaneBlock& block, std::span<const SoftBody> bodies,
                  std::span<const std::pair<Real, Real>> frictions)
{
    for (std::uint32_t lane = 0; lane < block.lanes; ++lane) {
        const auto l = static_cast<int>(lane);
        const SoftBody& a = bodies[block.bodyA[lane]];
        const SoftBody& b = bodies[block.bodyB[lane]];
        const Vec3 normal = laneOf(block.normal, l);
        for (LanePoint& p : block.points) {
            if (p.active[l] == 0) {
                continue;
            }
            p.relativeVelocity[l] = glm::dot(
                normal, relativeVelocityAt(a, b, laneOf(p.anchorA, l), laneOf(p.anchorB, l)));
            p.maxNormalImpulse[l] = 0.0;
            p.normalWork[l] = 0.0;
        }
        block.frictionWork[l] = 0.0;
        const auto [staticFriction, kineticFriction] = frictions[block.manifold[lane]];
        block.friction[l] = frictionAtCentre(
            relativeVelocityAt(a, b, laneOf(block.centreA, l), laneOf(block.centreB, l)), normal,
            staticFriction, kineticFriction);
    }
}

} // namespace

SoftLanes::SoftLanes() : m_storage(std::make_unique<Storage>()) {}

SoftLanes::~SoftLanes() = default;

SoftLanes::SoftLanes(const SoftLanes& other)
    : m_storage(std::make_unique<Storage>(*other.m_storage))
{
}

SoftLanes& SoftLanes::operator=(const SoftLanes& other)
{
    if (this != &other) {
        *m_storage = *other.m_storage;
    }
    return *this;
}

std::size_t SoftLanes::manifoldsPerBlock()
{
    return kLanes;
}

void SoftLanes::restart(std::span<const SoftBody> bodies,
                        std::span<const std::pair<Real, Real>> frictions, int threads)
{
    Storage& storage = *m_storage;
    // each block writes only itself, on the thread that sweeps it
    forEachBlockShare(storage, threads, [&](std::size_t first, std::size_t last) {
        for (std::size_t index = first; index < last; ++index) {
            restartBlock(storage.blocks[index], bodies, frictions);
        }
    });
}

void SoftLanes::pack(std::span<const SoftManifold> manifolds, const SoftColours& colours,
                     std::span<const SoftBody> bodies, int threads)
{
    pack([&](std::size_t index) { return manifolds[index]; }, colours, bodies, threads);
}

void SoftLanes::pack(const ManifoldSource& source, const SoftColours& colours,
                     std::span<const SoftBody> bodies, int threads)
{
    Storage& storage = *m_storage;
    storage.colourBlocks.assign(1, 0);
    storage.colourManifolds.clear();
    storage.anyThreadedColour = false;
    storage.halfColours = colours.halfColours;
    const std::size_t groups = colours.offsets.empty() ? 0 : colours.offsets.size() - 1;
    // every group but the last (the overflow) is a colour
    std::size_t blockCount = 0;
    for (std::size_t c = 0; c + 1 < groups; ++c) {
        const std::size_t size = colours.offsets[c + 1] - colours.offsets[c];
        blockCount += (size + kLanes - 1) / kLanes;
        storage.colourBlocks.push_back(blockCount);
        storage.colourManifolds.push_back(size);
        storage.anyThreadedColour =
            storage.anyThreadedColour || size >= kThreadedLaneManifolds;
    }
    // islands of every size take turns in one thread's lanes: the vector never shrinks, since
    // blocks constructed again after a smaller island would be cleared on the calling thread
    // (every block this island fills, packBlock empties), and it grows at least twofold, since
    // one grown to each larger island's size exactly would take fresh pages at every growth
    if (blockCount > storage.blocks.size()) {
        if (blockCount > storage.blocks.capacity()) {
            // every block is packed again below: none is moved to the new storage
            const std::size_t capacity = std::max(blockCount, 2 * storage.blocks.capacity());
            storage.blocks.clear();
            storage.blocks.reserve(capacity);
        }
        storage.blocks.resize(blockCount);
    }
    // the first manifold and the lanes of each block, so that the blocks (not the colours, of
    // very unequal sizes) are shared out over the threads, each writing only itself
    storage.firstManifold.resize(blockCount);
    storage.laneCount.resize(blockCount);
    std::size_t next = 0;
    for (std::size_t c = 0; c + 1 < groups; ++c) {
        const std::size_t end = colours.offsets[c + 1];
        for (std::size_t first = colours.offsets[c]; first < end; first += kLanes, ++next) {
            storage.firstManifold[next] = static_cast<std::uint32_t>(first);
            storage.laneCount[next] =
                static_cast<std::uint32_t>(std::min<std::size_t>(kLanes, end - first));
        }
    }
    // each block packed by the thread that sweeps it, so that its lines start in that cache
    forEachBlockShare(storage, threads, [&](std::size_t first, std::size_t last) {
        for (std::size_t b = first; b < last; ++b) {
            packBlock(storage.blocks[b], storage.firstManifold[b], storage.laneCount[b], source,
                      bodies);
        }
    });
}

void SoftLanes::warmStart(std::span<SoftBody> bodies, int threads)
{
    Storage& storage = *m_storage;
    forEachColour(storage, threads, [&](std::size_t first, std::size_t last) {
        warmStartBlocks({storage.blocks.data() + first, last - first}, bodies);
    });
}

void SoftLanes::warmStart(std::span<SoftBody> bodies, const PhaseTeam& team)
{
    Storage& storage = *m_storage;
    forEachColour(storage, team, [&](std::size_t first, std::size_t last) {
        warmStartBlocks({storage.blocks.data() + first, last - first}, bodies);
    });
}

namespace {

LaneSettings laneSettingsOf(const SoftSolveSettings& settings, bool useBias)
{
    const Softness& fixed = settings.staticSoftness;
    const Softness& moving = settings.dynamicSoftness;
    return LaneSettings{splat(fixed.biasRate),          splat(fixed.massScale),
                        splat(fixed.impulseScale),      splat(moving.biasRate),
                        splat(moving.massScale),        splat(moving.impulseScale),
                        splat(settings.inverseSubstep), splat(-settings.pushSpeed),
                        useBias};
}

} // namespace

void SoftLanes::solve(std::span<SoftBody> bodies, const SoftSolveSettings& settings,
                      bool useBias, int threads)
{
    Storage& storage = *m_storage;
    const LaneSettings lanes = laneSettingsOf(settings, useBias);
    forEachColour(storage, threads, [&](std::size_t first, std::size_t last) {
        solveBlocks({storage.blocks.data() + first, last - first}, bodies, lanes);
    });
}

void SoftLanes::solve(std::span<SoftBody> bodies, const SoftSolveSettings& settings,
                      bool useBias, const PhaseTeam& team)
{
    Storage& storage = *m_storage;
    const LaneSettings lanes = laneSettingsOf(settings, useBias);
    forEachColour(storage, team, [&](std::size_t first, std::size_t last) {
        solveBlocks({storage.blocks.data() + first, last - first}, bodies, lanes);
    });
}

} // namespace tumble
