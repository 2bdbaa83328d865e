// Items grouped by owner for threads: every item once, one owner a group, order kept (11.5c).
#include "step/owner_groups.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace tumble {
namespace {

TEST(OwnerGroups, EachGroupHoldsOneOwnersItemsInIncreasingOrder)
{
    std::mt19937 random(7);
    std::uniform_int_distribution<std::uint32_t> owner(0, 39);
    std::vector<std::uint32_t> ownerOf(500);
    for (std::uint32_t& o : ownerOf) {
        o = owner(random);
    }
    OwnerGroups groups;
    groups.build(ownerOf, 41);
    std::vector<int> seen(ownerOf.size(), 0);
    std::vector<int> groupsOfOwner(41, 0);
    for (std::size_t g = 0; g < groups.count(); ++g) {
        const auto items = groups.group(g);
        ASSERT_FALSE(items.empty());
        ++groupsOfOwner[ownerOf[items.front()]];
        for (std::size_t k = 0; k < items.size(); ++k) {
            EXPECT_EQ(ownerOf[items[k]], ownerOf[items.front()]);
            EXPECT_TRUE(k == 0 || items[k - 1] < items[k]);
            ++seen[items[k]];
        }
    }
    for (const int times : seen) {
        EXPECT_EQ(times, 1);
    }
    for (const int count : groupsOfOwner) {
        EXPECT_LE(count, 1);
    }
    // building again over fewer items reuses the buffers and forgets the last grouping
    groups.build(std::vector<std::uint32_t>{3, 1, 3}, 41);
    ASSERT_EQ(groups.count(), 2u);
    EXPECT_EQ(std::vector<std::uint32_t>(groups.group(0).begin(), groups.group(0).end()),
              std::vector<std::uint32_t>{1});
    EXPECT_EQ(std::vector<std::uint32_t>(groups.group(1).begin(), groups.group(1).end()),
              (std::vector<std::uint32_t>{0, 2}));
    groups.build({}, 41);
    EXPECT_EQ(groups.count(), 0u);
}

} // namespace
} // namespace tumble
