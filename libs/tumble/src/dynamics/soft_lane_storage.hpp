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

} // namespace soft_rows

struct SoftLanes::Storage {
    std::vector<soft_rows::LaneBlock> blocks;
    /// Colour c's blocks are [colourBlocks[c], colourBlocks[c + 1]); its manifold count.
    std::vector<std::size_t> colourBlocks;
    std::vector<std::size_t> colourManifolds;
    /// Each block's first manifold and the lanes it fills.
    std::vector<std::uint32_t> firstManifold;
    std::vector<std::uint32_t> laneCount;
    /// Whether some colour has kThreadedLaneManifolds or more.
    bool anyThreadedColour = false;
};

namespace soft_rows {

/// Calls `visit(first, last)` over the blocks of every colour, colour after colour, over
/// `threads`: a colour of kThreadedLaneManifolds or more split into one run of blocks a thread,
/// as equal as whole blocks allow (the blocks cost alike and the threads meet at the colour's
/// end), a smaller one on the first thread whole.
template <typename Storage, typename Visit>
void forEachColour(const Storage& storage, int threads, const Visit& visit)
{
    const int used = storage.anyThreadedColour ? threads : 1;
    parallelPhases(storage.colourManifolds.size(), used,
                   [&](std::size_t colour, std::size_t share, std::size_t shares) {
        const std::size_t begin = storage.colourBlocks[colour];
        const std::size_t end = storage.colourBlocks[colour + 1];
        if (storage.colourManifolds[colour] < kThreadedLaneManifolds || shares == 1) {
            if (share == 0) {
                visit(begin, end);
            }
            return;
        }
        const std::size_t blocks = end - begin;
        visit(begin + share * blocks / shares, begin + (share + 1) * blocks / shares);
    });
}

} // namespace soft_rows

} // namespace tumble
