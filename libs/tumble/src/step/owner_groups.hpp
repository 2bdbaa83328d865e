// Items grouped by the body whose state they write, so that groups can go to different threads
// (docs/physics/11-island-solver.md, (11.5c)).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace tumble {

/// Items [0, n) by owner: group g holds the items of one owner, in increasing order. Items of
/// one owner write that owner's state (its kept pair geometry, its warm-start cache), so two
/// groups can be worked on at once and each owner sees its items in the same order as in one
/// pass over all of them.
class OwnerGroups {
public:
    /// Groups items by `ownerOf[i]` < `ownerCount` (a counting sort, stable).
    void build(std::span<const std::uint32_t> ownerOf, std::size_t ownerCount);

    [[nodiscard]] std::size_t count() const { return m_start.empty() ? 0 : m_start.size() - 1; }
    [[nodiscard]] std::span<const std::uint32_t> group(std::size_t g) const
    {
        return std::span(m_items).subspan(m_start[g], m_start[g + 1] - m_start[g]);
    }

private:
    std::vector<std::uint32_t> m_items;
    std::vector<std::uint32_t> m_start;
    std::vector<std::uint32_t> m_offsets;
    std::vector<std::uint32_t> m_next;
};

} // namespace tumble
