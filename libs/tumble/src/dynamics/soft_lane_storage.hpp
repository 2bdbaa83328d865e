// What the soft step's lanes keep between their passes, and how a colour's blocks are shared
// over the threads (docs/physics/12-soft-step.md, (12.9)). For dynamics/soft_lane*.cpp only.
#pragma once

#include "dynamics/soft_lane_rows.hpp"
#include "dynamics/soft_lanes.hpp"
#include "large_buffer.hpp"
#include "parallel_for.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace tumble {

namespace soft_rows {

/// A colour of fewer manifolds than this is swept by one thread. In lanes a manifold costs a
/// quarter of what it costs alone, yet a colour of 64 still takes several times what handing
/// out its two shares does.
inline constexpr std::size_t kThreadedLaneManifolds = 64;

} // namespace soft_rows

struct SoftLanes::Storage {
    /// The last pack's blocks first (soft_rows::blockCountOf), then those of larger islands
    /// packed before it.
    std::vector<soft_rows::LaneBlock, LargeBufferAllocator<soft_rows::LaneBlock>> blocks;
    /// Colour c's blocks are [colourBlocks[c], colourBlocks[c + 1]); its manifold count.
    std::vector<std::size_t> colourBlocks;
    std::vector<std::size_t> colourManifolds;
    /// Each block's first manifold and the lanes it fills.
    std::vector<std::uint32_t> firstManifold;
    std::vector<std::uint32_t> laneCount;
    /// Whether some colour has kThreadedLaneManifolds or more.
    bool anyThreadedColour = false;
    /// SoftColours::halfColours of the colours packed.
    std::array<std::uint32_t, 2> halfColours{0, 0};
};

namespace soft_rows {

/// The blocks the last pack filled: the first ones of `blocks`, which keeps those of a larger
/// island packed before.
template <typename Storage>
std::size_t blockCountOf(const Storage& storage)
{
    return storage.colourBlocks.empty() ? 0 : storage.colourBlocks.back();
}

/// The blocks of a split island's halves (SoftColours::halfColours) that thread `share` of
/// `shares` sweeps: the first half's colours on the first thread, the second half's on the
/// second, each colour after colour with no barrier (the halves share no body); with one thread
/// both. [first, last) of the blocks; empty for a third thread.
template <typename Storage>
std::pair<std::size_t, std::size_t> halfBlocks(const Storage& storage, std::size_t share,
                                               std::size_t shares)
{
    const std::uint32_t firstHalf = storage.halfColours[0];
    const std::uint32_t bothHalves = firstHalf + storage.halfColours[1];
    if (shares == 1) {
        return {storage.colourBlocks[0], storage.colourBlocks[bothHalves]};
    }
    if (share >= 2) {
        return {0, 0};
    }
    return {storage.colourBlocks[share == 0 ? 0 : firstHalf],
            storage.colourBlocks[share == 0 ? firstHalf : bothHalves]};
}

/// The run of colour `colour`'s blocks that thread `share` of `shares` sweeps: a colour of
/// kThreadedLaneManifolds or more split into one run a thread, as equal as whole blocks allow
/// (the blocks cost alike and the threads meet at the colour's end), a smaller one on the first
/// thread whole.
template <typename Storage>
std::pair<std::size_t, std::size_t> colourShare(const Storage& storage, std::size_t colour,
                                                std::size_t share, std::size_t shares)
{
    const std::size_t begin = storage.colourBlocks[colour];
    const std::size_t end = storage.colourBlocks[colour + 1];
    if (storage.colourManifolds[colour] < kThreadedLaneManifolds || shares == 1) {
        return share == 0 ? std::pair{begin, end} : std::pair{begin, begin};
    }
    const std::size_t blocks = end - begin;
    return {begin + share * blocks / shares, begin + (share + 1) * blocks / shares};
}

/// Calls `visit(first, last)` over the blocks of every colour, in the colours' order, on the
/// team's threads: first the halves of a split island, a thread each (halfBlocks), then each
/// colour across the halves, or every colour of an island not split, shared as colourShare
/// says, the threads meeting after each but the last.
template <typename Storage, typename Visit>
void forEachColour(const Storage& storage, const PhaseTeam& team, const Visit& visit)
{
    const std::size_t halves = storage.halfColours[0] + storage.halfColours[1];
    const std::size_t colours = storage.colourManifolds.size();
    const std::size_t first = halves > 0 ? 1 : 0;
    const std::size_t phases = first + colours - halves;
    for (std::size_t phase = 0; phase < phases; ++phase) {
        const auto [begin, end] =
            phase < first ? halfBlocks(storage, team.share(), team.shares())
                          : colourShare(storage, halves + phase - first, team.share(),
                                        team.shares());
        if (begin < end) {
            visit(begin, end);
        }
        if (phase + 1 < phases) {
            team.sync();
        }
    }
}

/// The same in a region of its own over `threads`, or on the calling thread alone when no
/// colour is large enough to share and the island is not split.
template <typename Storage, typename Visit>
void forEachColour(const Storage& storage, int threads, const Visit& visit)
{
    const std::size_t halves = storage.halfColours[0] + storage.halfColours[1];
    if (halves == 0 && storage.colourManifolds.empty()) {
        return;
    }
    const bool shared = storage.anyThreadedColour || halves > 0;
    parallelTeam(shared ? threads : 1,
                 [&](const PhaseTeam& team) { forEachColour(storage, team, visit); });
}

/// Calls `visit(first, last)` over every block once, each on the thread forEachColour gives it,
/// with no barrier: for work that reads and writes only the blocks, so that each block stays in
/// the cache of the thread that sweeps it.
template <typename Storage, typename Visit>
void forEachBlockShare(const Storage& storage, int threads, const Visit& visit)
{
    const std::size_t halves = storage.halfColours[0] + storage.halfColours[1];
    const std::size_t colours = storage.colourManifolds.size();
    const int used = storage.anyThreadedColour || halves > 0 ? threads : 1;
    parallelPhases(1, used, [&](std::size_t, std::size_t share, std::size_t shares) {
        if (halves > 0) {
            const auto [begin, end] = halfBlocks(storage, share, shares);
            if (begin < end) {
                visit(begin, end);
            }
        }
        for (std::size_t colour = halves; colour < colours; ++colour) {
            const auto [begin, end] = colourShare(storage, colour, share, shares);
            if (begin < end) {
                visit(begin, end);
            }
        }
    });
}

} // namespace soft_rows

} // namespace tumble
