// Items grouped by owner: a stable counting sort.
#include "step/owner_groups.hpp"

namespace tumble {

void OwnerGroups::build(std::span<const std::uint32_t> ownerOf, std::size_t ownerCount)
{
    // m_offsets[o] is where owner o's items start in m_items, m_offsets[o + 1] where they end
    m_offsets.assign(ownerCount + 1, 0);
    for (const std::uint32_t owner : ownerOf) {
        ++m_offsets[owner + 1];
    }
    for (std::size_t owner = 1; owner <= ownerCount; ++owner) {
        m_offsets[owner] += m_offsets[owner - 1];
    }
    // items in increasing order within each owner
    m_next.assign(m_offsets.begin(), m_offsets.end() - 1);
    m_items.resize(ownerOf.size());
    for (std::uint32_t item = 0; item < ownerOf.size(); ++item) {
        m_items[m_next[ownerOf[item]]++] = item;
    }
    // an owner with no item makes no group
    m_start.clear();
    for (std::size_t owner = 0; owner < ownerCount; ++owner) {
        if (m_offsets[owner + 1] > m_offsets[owner]) {
            m_start.push_back(m_offsets[owner]);
        }
    }
    if (!m_start.empty()) {
        m_start.push_back(static_cast<std::uint32_t>(ownerOf.size()));
    }
}

} // namespace tumble
