// The soft step's lanes after the sub-steps: restitution lane by lane, and what each manifold
// packed leaves (docs/physics/12-soft-step.md, (12.6), (12.9)).
#include "dynamics/soft_lanes.hpp"

#include "dynamics/soft_lane_rows.hpp"
#include "dynamics/soft_lane_storage.hpp"
#include "parallel_for.hpp"

namespace tumble {

namespace {

using namespace lanes;
using namespace soft_rows;

/// The points of a lane's manifold: those its pack made active.
int pointsOf(const LaneBlock& block, std::uint32_t lane)
{
    int count = 0;
    while (count < 4 && block.points[count].active[lane] != 0) {
        ++count;
    }
    return count;
}

/// What restituteManifold reads and writes of a lane's manifold, as the manifold alone held it.
SoftManifold restitutionRowsOf(const LaneBlock& block, std::uint32_t lane)
{
    const auto l = static_cast<int>(lane);
    SoftManifold m;
    m.bodyA = block.bodyA[lane];
    m.bodyB = block.bodyB[lane];
    m.pointCount = pointsOf(block, lane);
    m.normal = laneOf(block.normal, l);
    m.restitution = block.restitution[lane];
    for (int k = 0; k < m.pointCount; ++k) {
        const LanePoint& from = block.points[k];
        SoftPoint& p = m.points[k];
        const LaneAngular angular = pointAngular(block, from);
        p.angularA = laneOf(angular.a, l);
        p.angularB = laneOf(angular.b, l);
        p.responseA = laneOf(times(block.inertiaA, angular.a), l);
        p.responseB = laneOf(times(block.inertiaB, angular.b), l);
        p.normalMass = from.normalMass[lane];
        p.relativeVelocity = from.relativeVelocity[lane];
        p.normalImpulse = from.normalImpulse[lane];
        p.maxNormalImpulse = from.maxNormalImpulse[lane];
        p.normalWork = from.normalWork[lane];
    }
    return m;
}

/// Whether restituteManifold acts on a point of the lane's manifold (12.6): one that approached
/// faster than the threshold and pushed in the sub-steps.
bool bouncesInLane(const LaneBlock& block, std::uint32_t lane, Real threshold)
{
    for (int k = 0; k < 4 && block.points[k].active[lane] != 0; ++k) {
        const LanePoint& p = block.points[k];
        if (bounces(p.relativeVelocity[lane], p.maxNormalImpulse[lane], threshold)) {
            return true;
        }
    }
    return false;
}

/// restituteManifold on each bouncing lane of the blocks, its impulses and work written back;
/// a lane whose points none bounce is left as it is (the manifold's pass would change nothing).
void restituteBlocks(std::span<LaneBlock> blocks, std::span<SoftBody> bodies, Real threshold)
{
    for (LaneBlock& block : blocks) {
        for (std::uint32_t lane = 0; lane < block.lanes; ++lane) {
            if (block.restitution[lane] == 0.0 || !bouncesInLane(block, lane, threshold)) {
                continue;
            }
            SoftManifold m = restitutionRowsOf(block, lane);
            restituteManifold(m, bodies, threshold);
            for (int k = 0; k < m.pointCount; ++k) {
                block.points[k].normalImpulse[lane] = m.points[k].normalImpulse;
                block.points[k].normalWork[lane] = m.points[k].normalWork;
            }
        }
    }
}

/// softResultOf for each lane of `block`, into the manifold's index in `results`.
void resultsOfBlock(const LaneBlock& block, std::span<SoftContactResult> results)
{
    for (std::uint32_t lane = 0; lane < block.lanes; ++lane) {
        const auto l = static_cast<int>(lane);
        SoftContactResult& result = results[block.manifold[lane]];
        result.pointCount = pointsOf(block, lane);
        for (int k = 0; k < result.pointCount; ++k) {
            result.normalImpulses[k] = block.points[k].normalImpulse[lane];
            result.normalWork[k] = block.points[k].normalWork[lane];
        }
        // as softResultOf forms it
        result.frictionImpulse = block.frictionImpulse1[lane] * laneOf(block.tangent1, l) +
                                 block.frictionImpulse2[lane] * laneOf(block.tangent2, l);
        result.twistImpulse = block.twistImpulse[lane];
        result.frictionWork = block.frictionWork[lane];
    }
}

} // namespace

void SoftLanes::restitute(std::span<SoftBody> bodies, Real threshold, int threads)
{
    Storage& storage = *m_storage;
    forEachColour(storage, threads, [&](std::size_t first, std::size_t last) {
        restituteBlocks({storage.blocks.data() + first, last - first}, bodies, threshold);
    });
}

void SoftLanes::restitute(std::span<SoftBody> bodies, Real threshold, const PhaseTeam& team)
{
    Storage& storage = *m_storage;
    forEachColour(storage, team, [&](std::size_t first, std::size_t last) {
        restituteBlocks({storage.blocks.data() + first, last - first}, bodies, threshold);
    });
}

void SoftLanes::results(std::span<SoftContactResult> results, int threads) const
{
    const Storage& storage = *m_storage;
    forEachBlockShare(storage, threads, [&](std::size_t first, std::size_t last) {
        for (std::size_t b = first; b < last; ++b) {
            resultsOfBlock(storage.blocks[b], results);
        }
    });
}

void SoftLanes::work(std::vector<SoftBlockWork>& blockWork, std::span<std::uint8_t> pushed,
                     int threads) const
{
    const Storage& storage = *m_storage;
    blockWork.resize(blockCountOf(storage));
    forEachBlockShare(storage, threads, [&](std::size_t first, std::size_t last) {
        for (std::size_t b = first; b < last; ++b) {
            const LaneBlock& block = storage.blocks[b];
            SoftBlockWork& work = blockWork[b];
            work = SoftBlockWork{};
            for (std::uint32_t lane = 0; lane < block.lanes; ++lane) {
                bool pushes = false;
                for (int k = 0; k < pointsOf(block, lane); ++k) {
                    work.normal += block.points[k].normalWork[lane];
                    pushes = pushes || block.points[k].normalImpulse[lane] > 0.0;
                }
                work.friction += block.frictionWork[lane];
                pushed[block.manifold[lane]] = pushes ? 1 : 0;
            }
        }
    });
}

void SoftLanes::unpack(std::span<SoftManifold> manifolds, int threads) const
{
    const Storage& storage = *m_storage;
    parallelFor(blockCountOf(storage), threads, [&](std::size_t b) {
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
