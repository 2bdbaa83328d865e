// Sort and sweep along the axis of largest spread (docs/physics/10-broad-phase.md;
// Baraff 1992 on coherence; Ericson 2005, 7.5).
#include "collision/broad_phase.hpp"

#include "parallel_for.hpp"

#include <algorithm>
#include <cstddef>

namespace tumble {
namespace {

/// Sweep order: by the low end along the sweep axis, then by proxy index, a strict total order,
/// so the sorted sequence is unique and does not depend on the order it was sorted from.
template <typename Entry>
bool sweepsBefore(const Entry& first, const Entry& second, int axis)
{
    const Real firstMin = first.box.min[axis];
    const Real secondMin = second.box.min[axis];
    return firstMin < secondMin || (firstMin == secondMin && first.proxy < second.proxy);
}

/// A shared sweep gives each share at least this many entries, so a share pays for its start.
constexpr std::size_t kEntriesPerShare = 128;

/// Moves allowed to the insertion sort, per entry, before it gives way to std::sort. Boxes that
/// pass a few others need fewer; a pile whose layers share one low end, jittering, reorders
/// each layer at random, and then the moves made before the hand-over (at most 2n, against the
/// roughly n log2 n comparisons of std::sort) are all that the kept order costs.
constexpr std::size_t kInsertionMovesPerEntry = 2;

/// Each box is swept grown by this share of its largest side on every side, so a box that moves
/// by less keeps the last sweep's pairs: a resting body, which moves by rounding, never leaves
/// its grown box, while the sweep meets only a few more candidates than with the boxes
/// themselves.
constexpr Real kGrowthShare = 1.0 / 64.0;

/// Whether `inner` lies in the closed box `outer`.
bool contains(const Aabb& outer, const Aabb& inner)
{
    return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y &&
           outer.min.z <= inner.min.z && inner.max.x <= outer.max.x &&
           inner.max.y <= outer.max.y && inner.max.z <= outer.max.z;
}

} // namespace

int axisOfLargestSpread(std::span<const BroadPhaseProxy> proxies)
{
    if (proxies.empty()) {
        return 0;
    }
    // the mean first, then the spread about it: two passes, so large coordinates do not cancel
    Vec3 mean(0.0);
    for (const BroadPhaseProxy& proxy : proxies) {
        mean += 0.5 * (proxy.box.min + proxy.box.max);
    }
    mean /= static_cast<Real>(proxies.size());
    Vec3 spread(0.0);
    for (const BroadPhaseProxy& proxy : proxies) {
        const Vec3 offset = 0.5 * (proxy.box.min + proxy.box.max) - mean;
        spread += offset * offset;
    }
    int axis = 0;
    for (int candidate = 1; candidate < 3; ++candidate) {
        if (spread[candidate] > spread[axis]) {
            axis = candidate;
        }
    }
    return axis;
}

void BroadPhase::update(std::span<const BroadPhaseProxy> proxies, int threads)
{
    // (10.3a): the grown boxes' pairs hold every overlapping pair while each box stays in its
    // grown box, so they are swept again only when one leaves
    m_sweptLastUpdate = !grownBoxesHold(proxies);
    if (m_sweptLastUpdate) {
        growBoxes(proxies);
        refreshEntries(m_grown, axisOfLargestSpread(m_grown));
        sortEntries();
        sweep(threads);
    }
    keepOverlapping(proxies);
}

bool BroadPhase::grownBoxesHold(std::span<const BroadPhaseProxy> proxies) const
{
    if (m_grown.size() != proxies.size()) {
        return false;
    }
    for (std::size_t i = 0; i < proxies.size(); ++i) {
        // a proxy that became movable (or static) pairs with boxes its old kind skipped
        if (m_grown[i].movable != proxies[i].movable || !contains(m_grown[i].box, proxies[i].box)) {
            return false;
        }
    }
    return true;
}

void BroadPhase::growBoxes(std::span<const BroadPhaseProxy> proxies)
{
    m_grown.assign(proxies.begin(), proxies.end());
    for (BroadPhaseProxy& proxy : m_grown) {
        const Vec3 size = proxy.box.max - proxy.box.min;
        proxy.box = expanded(proxy.box, kGrowthShare * std::max({size.x, size.y, size.z}));
    }
}

void BroadPhase::keepOverlapping(std::span<const BroadPhaseProxy> proxies)
{
    // the grown pairs are sorted and distinct, so the pairs kept are too
    m_pairs.clear();
    for (const ProxyPair& pair : m_grownPairs) {
        if (overlaps(proxies[pair.a].box, proxies[pair.b].box)) {
            m_pairs.push_back(pair);
        }
    }
}

void BroadPhase::refreshEntries(std::span<const BroadPhaseProxy> proxies, int axis)
{
    const bool keptOrderFits = m_entries.size() == proxies.size() && axis == m_axis;
    m_axis = axis;
    if (!keptOrderFits) {
        // a new set or a new axis: start from the input order, std::sort does the rest
        m_entries.resize(proxies.size());
        for (std::size_t i = 0; i < proxies.size(); ++i) {
            m_entries[i].proxy = static_cast<std::uint32_t>(i);
        }
    }
    // the kept order with this step's boxes
    for (Entry& entry : m_entries) {
        const BroadPhaseProxy& proxy = proxies[entry.proxy];
        entry.box = proxy.box;
        entry.movable = proxy.movable;
    }
    if (!keptOrderFits) {
        sortFromScratch();
    }
}

void BroadPhase::sortFromScratch()
{
    const int axis = m_axis;
    std::sort(m_entries.begin(), m_entries.end(),
              [axis](const Entry& a, const Entry& b) { return sweepsBefore(a, b, axis); });
}

void BroadPhase::sortEntries()
{
    // insertion sort from the kept order: near-linear when few boxes change places
    const int axis = m_axis;
    const std::size_t budget = kInsertionMovesPerEntry * m_entries.size();
    std::size_t moves = 0;
    for (std::size_t i = 1; i < m_entries.size(); ++i) {
        const Entry moving = m_entries[i];
        std::size_t slot = i;
        while (slot > 0 && sweepsBefore(moving, m_entries[slot - 1], axis)) {
            m_entries[slot] = m_entries[slot - 1];
            --slot;
            ++moves;
        }
        m_entries[slot] = moving;
        if (moves > budget) {
            // the boxes moved far (a teleport, a shuffled input): the rest as a whole
            sortFromScratch();
            return;
        }
    }
}

void BroadPhase::sweepFrom(std::size_t begin, std::size_t end,
                           std::vector<ProxyPair>& pairs) const
{
    // every box meets the boxes that start along the axis before it ends; the other two axes
    // decide (Ericson 2005, 7.5)
    const int axis = m_axis;
    const std::size_t count = m_entries.size();
    for (std::size_t i = begin; i < end; ++i) {
        const Entry& first = m_entries[i];
        const Real reach = first.box.max[axis];
        for (std::size_t j = i + 1; j < count && m_entries[j].box.min[axis] <= reach; ++j) {
            const Entry& second = m_entries[j];
            if ((first.movable || second.movable) && overlaps(first.box, second.box)) {
                pairs.push_back(ProxyPair{std::min(first.proxy, second.proxy),
                                          std::max(first.proxy, second.proxy)});
            }
        }
    }
}

void BroadPhase::sweep(int threads)
{
    m_grownPairs.clear();
    const std::size_t count = m_entries.size();
    if (threads <= 1 || count < kEntriesPerShare * static_cast<std::size_t>(threads)) {
        sweepFrom(0, count, m_grownPairs);
    } else {
        // each share of the sorted entries finds the pairs of its first boxes; as many shares
        // to each thread
        const auto threadCount = static_cast<std::size_t>(threads);
        const std::size_t shares = count / kEntriesPerShare / threadCount * threadCount;
        m_sharePairs.resize(shares);
        parallelFor(shares, threads, [&](std::size_t share) {
            std::vector<ProxyPair>& pairs = m_sharePairs[share];
            pairs.clear();
            sweepFrom(count * share / shares, count * (share + 1) / shares, pairs);
        });
        for (const std::vector<ProxyPair>& pairs : m_sharePairs) {
            m_grownPairs.insert(m_grownPairs.end(), pairs.begin(), pairs.end());
        }
    }
    // the pairs in proxy order, not sweep order, so they depend on the proxies alone
    sortPairs(count);
}

void BroadPhase::sortPairs(std::size_t proxyCount)
{
    // a counting sort on the first proxy (Cormen et al. 2009, 8.2), then each proxy's few
    // pairs by the second: linear in the pairs, where a comparison sort took a third of a sweep
    m_pairStarts.assign(proxyCount + 1, 0);
    for (const ProxyPair& pair : m_grownPairs) {
        ++m_pairStarts[pair.a + 1];
    }
    for (std::size_t proxy = 0; proxy < proxyCount; ++proxy) {
        m_pairStarts[proxy + 1] += m_pairStarts[proxy];
    }
    m_sortedPairs.resize(m_grownPairs.size());
    for (const ProxyPair& pair : m_grownPairs) {
        m_sortedPairs[m_pairStarts[pair.a]++] = pair;
    }
    // each start has moved to the next proxy's: the runs are [starts[a - 1], starts[a])
    std::uint32_t first = 0;
    for (std::size_t proxy = 0; proxy < proxyCount; ++proxy) {
        const std::uint32_t last = m_pairStarts[proxy];
        std::sort(m_sortedPairs.begin() + static_cast<std::ptrdiff_t>(first),
                  m_sortedPairs.begin() + static_cast<std::ptrdiff_t>(last));
        first = last;
    }
    std::swap(m_grownPairs, m_sortedPairs);
}

} // namespace tumble
