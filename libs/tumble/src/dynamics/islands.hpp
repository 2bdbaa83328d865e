// Islands: the groups of awake dynamic bodies joined through constraints, found by union-find
// (docs/physics/10-broad-phase.md, (10.4)).
#pragma once

#include "collision/broad_phase.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace tumble {

/// The island of a body that belongs to none (static or asleep).
inline constexpr std::uint32_t kNoIsland = std::numeric_limits<std::uint32_t>::max();

/// Awake dynamic bodies grouped into islands. Island k holds bodies[offsets[k] .. offsets[k+1]),
/// in ascending order; islands are ordered by their smallest body.
struct Islands {
    std::vector<std::uint32_t> bodies;
    /// One more entry than there are islands; offsets[0] = 0.
    std::vector<std::uint32_t> offsets{0};
    /// For every body, its island, or kNoIsland.
    std::vector<std::uint32_t> islandOfBody;

    std::size_t count() const { return offsets.size() - 1; }

    std::span<const std::uint32_t> island(std::size_t k) const
    {
        return std::span<const std::uint32_t>(bodies).subspan(offsets[k],
                                                              offsets[k + 1] - offsets[k]);
    }
};

/// The islands of `bodyCount` bodies of which those with isDynamicAwake[i] != 0 take part.
/// `links` hold body indices (a constraint between bodies a and b); a link joins two bodies only
/// when both are dynamic and awake, so a static floor joins nothing (10.4). The result depends
/// only on which bodies are linked, not on the order or orientation of the links.
Islands buildIslands(std::size_t bodyCount, std::span<const std::uint8_t> isDynamicAwake,
                     std::span<const ProxyPair> links);

/// The links of each island: island k holds links[offsets[k] .. offsets[k+1]).
struct IslandLinks {
    /// Indices into the links span, ascending within an island.
    std::vector<std::uint32_t> links;
    /// One more entry than there are islands.
    std::vector<std::uint32_t> offsets{0};

    std::span<const std::uint32_t> island(std::size_t k) const
    {
        return std::span<const std::uint32_t>(links).subspan(offsets[k],
                                                             offsets[k + 1] - offsets[k]);
    }
};

/// Sorts the links into the islands of their awake dynamic ends (a link to a static body belongs
/// to the island of its dynamic end; a link with no awake dynamic end to none).
IslandLinks linksOf(const Islands& islands, std::span<const ProxyPair> links);

} // namespace tumble
