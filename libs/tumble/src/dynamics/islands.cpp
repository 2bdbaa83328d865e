// Islands by union-find with path halving and union by size (Tarjan and van Leeuwen 1984;
// docs/physics/10-broad-phase.md, (10.4)).
#include "dynamics/islands.hpp"

#include "tumble_assert.hpp"

#include <utility>

namespace tumble {
namespace {

/// Disjoint sets of body indices.
class DisjointSets {
public:
    explicit DisjointSets(std::size_t count) : m_parent(count), m_size(count, 1)
    {
        for (std::size_t i = 0; i < count; ++i) {
            m_parent[i] = static_cast<std::uint32_t>(i);
        }
    }

    /// The representative of the set of `element`; halves the path on the way up.
    std::uint32_t find(std::uint32_t element)
    {
        while (m_parent[element] != element) {
            m_parent[element] = m_parent[m_parent[element]];
            element = m_parent[element];
        }
        return element;
    }

    /// Joins the sets of `first` and `second`; the larger set's root stays root.
    void unite(std::uint32_t first, std::uint32_t second)
    {
        std::uint32_t rootFirst = find(first);
        std::uint32_t rootSecond = find(second);
        if (rootFirst == rootSecond) {
            return;
        }
        if (m_size[rootFirst] < m_size[rootSecond]) {
            std::swap(rootFirst, rootSecond);
        }
        m_parent[rootSecond] = rootFirst;
        m_size[rootFirst] += m_size[rootSecond];
    }

private:
    std::vector<std::uint32_t> m_parent;
    std::vector<std::uint32_t> m_size;
};

} // namespace

Islands buildIslands(std::size_t bodyCount, std::span<const std::uint8_t> isDynamicAwake,
                     std::span<const ProxyPair> links)
{
    TUMBLE_ASSERT(isDynamicAwake.size() == bodyCount);
    // join the two ends of every link between awake dynamic bodies (10.4)
    DisjointSets sets(bodyCount);
    for (const ProxyPair& link : links) {
        TUMBLE_ASSERT(link.a < bodyCount && link.b < bodyCount);
        if (isDynamicAwake[link.a] && isDynamicAwake[link.b]) {
            sets.unite(link.a, link.b);
        }
    }
    // number the sets in the order of their smallest body, and count their bodies
    Islands islands;
    islands.islandOfBody.assign(bodyCount, kNoIsland);
    std::vector<std::uint32_t> islandOfRoot(bodyCount, kNoIsland);
    std::vector<std::uint32_t> sizes;
    for (std::uint32_t body = 0; body < bodyCount; ++body) {
        if (!isDynamicAwake[body]) {
            continue;
        }
        std::uint32_t& island = islandOfRoot[sets.find(body)];
        if (island == kNoIsland) {
            island = static_cast<std::uint32_t>(sizes.size());
            sizes.push_back(0);
        }
        islands.islandOfBody[body] = island;
        ++sizes[island];
    }
    // counting sort by island; ascending bodies within each, as they are visited in order
    islands.offsets.assign(sizes.size() + 1, 0);
    for (std::size_t k = 0; k < sizes.size(); ++k) {
        islands.offsets[k + 1] = islands.offsets[k] + sizes[k];
    }
    islands.bodies.resize(islands.offsets.back());
    std::vector<std::uint32_t> next(islands.offsets.begin(), islands.offsets.end() - 1);
    for (std::uint32_t body = 0; body < bodyCount; ++body) {
        if (islands.islandOfBody[body] != kNoIsland) {
            islands.bodies[next[islands.islandOfBody[body]]++] = body;
        }
    }
    return islands;
}

IslandLinks linksOf(const Islands& islands, std::span<const ProxyPair> links)
{
    // each link goes to the island of an awake dynamic end; both ends share it when both are
    const auto islandOfLink = [&islands](const ProxyPair& link) {
        const std::uint32_t first = islands.islandOfBody[link.a];
        return first != kNoIsland ? first : islands.islandOfBody[link.b];
    };
    IslandLinks result;
    result.offsets.assign(islands.count() + 1, 0);
    for (const ProxyPair& link : links) {
        const std::uint32_t island = islandOfLink(link);
        if (island != kNoIsland) {
            ++result.offsets[island + 1];
        }
    }
    for (std::size_t k = 0; k < islands.count(); ++k) {
        result.offsets[k + 1] += result.offsets[k];
    }
    // counting sort: links visited in order, so ascending within each island
    result.links.resize(result.offsets.back());
    std::vector<std::uint32_t> next(result.offsets.begin(), result.offsets.end() - 1);
    for (std::uint32_t i = 0; i < links.size(); ++i) {
        const std::uint32_t island = islandOfLink(links[i]);
        if (island != kNoIsland) {
            result.links[next[island]++] = i;
        }
    }
    return result;
}

} // namespace tumble
