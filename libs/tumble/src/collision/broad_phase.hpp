// Sort and sweep: the pairs of overlapping proxy boxes, from a sorted order kept between steps
// (docs/physics/10-broad-phase.md; docs/decisions/0006-broad-phase.md).
#pragma once

#include "collision/aabb.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace tumble {

/// One body's box as the broad phase sees it.
struct BroadPhaseProxy {
    Aabb box;
    /// The body the box belongs to; carried for the caller, unused by the sweep.
    std::uint32_t body = 0;
    /// False for a static body: its box pairs only with movable boxes.
    bool movable = true;
};

/// Two proxy indices with a < b, as the broad phase reports them; islands and colouring read
/// the same pair as two body indices, in either order.
struct ProxyPair {
    std::uint32_t a = 0;
    std::uint32_t b = 0;

    friend auto operator<=>(const ProxyPair&, const ProxyPair&) = default;
};

/// Finds the overlapping pairs of a span of proxies. The proxies' boxes, grown by a share of
/// their size, are sorted along one axis by their low end and swept; the order is kept, so when
/// the boxes barely move the next sort is an insertion sort of near-linear cost. While every
/// box stays inside its grown box and no proxy changes its kind, the grown boxes' pairs are
/// kept and only tested again on the boxes themselves. The result depends only on the proxies.
class BroadPhase {
public:
    /// Finds the pairs of `proxies` whose boxes overlap (touching counts) and of which at least
    /// one is movable. The sweep spreads over `threads`; the pairs are the same for any number.
    void update(std::span<const BroadPhaseProxy> proxies, int threads = 1);

    /// The pairs of the last update: proxy indices a < b, sorted lexicographically, each once.
    std::span<const ProxyPair> pairs() const { return m_pairs; }

    /// The world axis (0, 1, 2) of the last sweep: the one of largest spread of the box centres.
    int sweepAxis() const { return m_axis; }
    /// Whether the last update swept the boxes again, rather than keeping the grown boxes'
    /// pairs.
    bool sweptLastUpdate() const { return m_sweptLastUpdate; }

private:
    /// A proxy's box and flags, copied in sweep order so the sweep reads memory in sequence.
    struct Entry {
        Aabb box;
        std::uint32_t proxy = 0;
        bool movable = true;
    };

    [[nodiscard]] bool grownBoxesHold(std::span<const BroadPhaseProxy> proxies) const;
    void growBoxes(std::span<const BroadPhaseProxy> proxies);
    void keepOverlapping(std::span<const BroadPhaseProxy> proxies);
    void refreshEntries(std::span<const BroadPhaseProxy> proxies, int axis);
    void sortEntries();
    void sortFromScratch();
    void sweep(int threads);
    /// m_grownPairs in proxy order, a then b; every proxy index below `proxyCount`.
    void sortPairs(std::size_t proxyCount);
    void sweepFrom(std::size_t begin, std::size_t end, std::vector<ProxyPair>& pairs) const;

    std::vector<Entry> m_entries;
    /// The proxies of the last sweep, each box grown by kGrowthShare of its largest side.
    std::vector<BroadPhaseProxy> m_grown;
    /// The pairs of the grown boxes: a superset of the pairs while each box stays in its own.
    std::vector<ProxyPair> m_grownPairs;
    std::vector<ProxyPair> m_pairs;
    bool m_sweptLastUpdate = false;
    /// The pairs found from each share of the sorted entries, when the sweep is shared.
    std::vector<std::vector<ProxyPair>> m_sharePairs;
    /// sortPairs' counts and places by first proxy, and the pairs it places.
    std::vector<std::uint32_t> m_pairStarts;
    std::vector<ProxyPair> m_sortedPairs;
    int m_axis = 0;
};

/// The axis (0, 1, 2) along which the centres of the boxes vary most (largest variance); ties
/// go to the lower axis.
int axisOfLargestSpread(std::span<const BroadPhaseProxy> proxies);

} // namespace tumble
