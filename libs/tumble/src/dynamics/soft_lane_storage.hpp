// What the soft step's lanes keep between their passes, and how a colour's blocks are shared
// over the threads (docs/physics/12-soft-step.md, (12.9)). For dynamics/soft_lane*.cpp only.
#pragma once

#include "dynamics/soft_lane_rows.hpp"
#include "dynamics/soft_lanes.hpp"
#include "parallel_for.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace tumble {

namespace soft_rows {

/// A colour of fewer manifolds than this is swept by one thread. In lanes a manifold costs a
/// quarter of what it costs alone, yet a colour of 64 still takes several times what handing
/// out its two shares does.
inline constexpr std::size_t kThreadedLaneManifolds = 64;

/// Calls `visit(first, last)` over a colour's blocks [begin, end): split into `threads` runs of
/// blocks as equal as whole blocks allow for a colour of kThreadedLaneManifolds or more, else
/// at once. A block costs about the same as any other and the threads meet at the colour's
/// end, so equal runs keep the threads' waits short.
template <typename Visit>
void forEachShare(std::size_t begin, std::size_t end, std::size_t manifolds, int threads,
                  const Visit& visit)
{
    if (manifolds < kThreadedLaneManifolds || threads < 2) {
        visit(begin, end);
        return;
    }
    const auto shares = static_cast<std::size_t>(threads);
    const std::size_t blocks = end - begin;
    parallelFor(shares, threads, [&](std::size_t share) {
        visit(begin + share * blocks / shares, begin + (share + 1) * blocks / shares);
    });
}

} // namespace soft_rows

struct SoftLanes::Storage {
    std::vector<soft_rows::LaneBlock> blocks;
    /// Colour c's blocks are [colourBlocks[c], colourBlocks[c + 1]); its manifold count.
    std::vector<std::size_t> colourBlocks;
    std::vector<std::size_t> colourManifolds;
    /// Each block's first manifold and the lanes it fills.
    std::vector<std::uint32_t> firstManifold;
    std::vector<std::uint32_t> laneCount;
};

} // namespace tumble
