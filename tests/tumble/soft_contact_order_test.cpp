// The soft step's contacts in colour order (docs/physics/12-soft-step.md, (12.9)): every contact
// once, no dynamic body twice in a colour, a large island's halves apart, each colour's contacts
// by their lower dynamic body, and the same tables whether they are made afresh or kept from the
// last step for the same contacts.
#include "step/soft_contact_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace tumble {
namespace {

/// `count` contacts between random pairs of `bodies` dynamic bodies, a fifth against the static
/// body (index `bodies`).
std::vector<IslandContact> randomContacts(std::uint32_t seed, std::uint32_t bodies, int count)
{
    std::mt19937 random(seed);
    std::uniform_int_distribution<std::uint32_t> pick(0, bodies - 1);
    std::vector<IslandContact> contacts(static_cast<std::size_t>(count));
    for (IslandContact& contact : contacts) {
        contact.solverB = pick(random);
        contact.solverA = random() % 5 == 0 ? bodies : pick(random);
        if (contact.solverA == contact.solverB) {
            contact.solverA = bodies;
        }
    }
    return contacts;
}

void expectValidOrder(const std::vector<IslandContact>& contacts, std::uint32_t bodies,
                      const SoftContactOrder& order)
{
    const std::vector<std::uint32_t>& offsets = order.colours.offsets;
    ASSERT_EQ(order.colourOrder.size(), contacts.size());
    ASSERT_EQ(offsets.back(), contacts.size());
    std::set<std::uint32_t> seen(order.colourOrder.begin(), order.colourOrder.end());
    EXPECT_EQ(seen.size(), contacts.size());
    for (std::size_t k = 0; k < contacts.size(); ++k) {
        const std::uint32_t contact = order.colourOrder[k];
        EXPECT_EQ(order.colourPosition[contact], k);
        EXPECT_EQ(order.colourEnds[k].a, contacts[contact].solverA);
        EXPECT_EQ(order.colourEnds[k].b, contacts[contact].solverB);
    }
    // every group but the last (the overflow) moves each dynamic body at most once
    for (std::size_t c = 0; c + 2 < offsets.size(); ++c) {
        std::set<std::uint32_t> moved;
        for (std::uint32_t k = offsets[c]; k < offsets[c + 1]; ++k) {
            for (const std::uint32_t side : {order.colourEnds[k].a, order.colourEnds[k].b}) {
                if (side != bodies) {
                    EXPECT_TRUE(moved.insert(side).second) << "colour " << c << " body " << side;
                }
            }
        }
    }
}

void expectSameOrder(const SoftContactOrder& one, const SoftContactOrder& other)
{
    EXPECT_EQ(one.colourOrder, other.colourOrder);
    EXPECT_EQ(one.colourPosition, other.colourPosition);
    EXPECT_EQ(one.colourEnds, other.colourEnds);
    EXPECT_EQ(one.colours.offsets, other.colours.offsets);
    EXPECT_EQ(one.colours.halfColours, other.colours.halfColours);
}

/// The lower dynamic body of the k-th contact in colour order.
std::uint32_t lowerDynamic(const SoftContactOrder& order, std::size_t k, std::uint32_t bodies)
{
    const ProxyPair& ends = order.colourEnds[k];
    return std::min(ends.a < bodies ? ends.a : bodies, ends.b < bodies ? ends.b : bodies);
}

TEST(SoftContactOrder, ColoursEveryContactOnceAndNoBodyTwiceAColour)
{
    const std::vector<IslandContact> contacts = randomContacts(1, 40, 300);
    SoftContactOrder order;
    orderSoftContacts(contacts, 40, 1, order);
    expectValidOrder(contacts, 40, order);
    EXPECT_GT(order.colours.offsets.size(), 4u);
}

TEST(SoftContactOrder, ASmallIslandIsNotSplitAndEachColourComesByItsLowerBody)
{
    const std::vector<IslandContact> contacts = randomContacts(4, 40, 300);
    SoftContactOrder order;
    orderSoftContacts(contacts, 40, 1, order);
    EXPECT_EQ(order.colours.halfColours[0], 0u);
    EXPECT_EQ(order.colours.halfColours[1], 0u);
    const std::vector<std::uint32_t>& offsets = order.colours.offsets;
    for (std::size_t c = 0; c + 2 < offsets.size(); ++c) {
        for (std::uint32_t k = offsets[c] + 1; k < offsets[c + 1]; ++k) {
            EXPECT_LE(lowerDynamic(order, k - 1, 40), lowerDynamic(order, k, 40)) << c;
        }
    }
}

TEST(SoftContactOrder, ALargeIslandsHalvesComeFirstEachInItsOwnColours)
{
    // 1 200 contacts (a large island) among 400 bodies, split at halfSplit: the first
    // halfColours[0] colours hold only contacts of bodies before it (or the static body), the
    // next halfColours[1] only of bodies from it on, the rest one of each; the halves hold as
    // many contacts as moving the split by one body can match
    constexpr std::uint32_t bodies = 400;
    const std::vector<IslandContact> contacts = randomContacts(5, bodies, 1200);
    SoftContactOrder order;
    orderSoftContacts(contacts, bodies, 1, order);
    expectValidOrder(contacts, bodies, order);
    const auto [first, second] = order.colours.halfColours;
    const std::uint32_t split = order.colours.halfSplit;
    ASSERT_GT(first, 0u);
    ASSERT_GT(second, 0u);
    ASSERT_GT(split, 0u);
    ASSERT_LT(split, bodies);
    const std::vector<std::uint32_t>& offsets = order.colours.offsets;
    const std::size_t colours = offsets.size() - 2;
    ASSERT_GT(colours, first + second);
    const auto halfOf = [&](std::uint32_t body) { return body < split ? 0 : 1; };
    std::vector<std::size_t> inGroup(3, 0);
    for (std::size_t c = 0; c < colours; ++c) {
        const std::size_t expected = c < first ? 0 : (c < first + second ? 1 : 2);
        for (std::uint32_t k = offsets[c]; k < offsets[c + 1]; ++k) {
            const ProxyPair& ends = order.colourEnds[k];
            const int a = ends.a == bodies ? -1 : halfOf(ends.a);
            const int b = ends.b == bodies ? -1 : halfOf(ends.b);
            const int group = a < 0 ? b : (b < 0 || a == b ? a : 2);
            EXPECT_EQ(static_cast<std::size_t>(group), expected) << "colour " << c;
            ++inGroup[expected];
        }
    }
    std::vector<std::size_t> ofBody(bodies + 1, 0);
    for (const IslandContact& contact : contacts) {
        ++ofBody[contact.solverA];
        ++ofBody[contact.solverB];
    }
    const std::size_t most = *std::max_element(ofBody.begin(), ofBody.end() - 1);
    EXPECT_LE(inGroup[0] > inGroup[1] ? inGroup[0] - inGroup[1] : inGroup[1] - inGroup[0], most);
}

TEST(SoftContactOrder, KeptTablesAreTheTablesMadeAfresh)
{
    const std::vector<IslandContact> first = randomContacts(2, 50, 400);
    std::vector<IslandContact> changed = first;
    std::swap(changed[10].solverA, changed[10].solverB);
    const std::vector<IslandContact> other = randomContacts(3, 50, 400);
    // one order through a settled step (the same contacts again), one changed contact, another
    // island of the same size and count, and the same contacts on a larger island
    using Step = std::pair<const std::vector<IslandContact>*, std::uint32_t>;
    const std::vector<Step> steps{{&first, 50}, {&first, 50}, {&changed, 50}, {&other, 50},
                                  {&other, 60}};
    SoftContactOrder kept;
    for (const auto& [contacts, bodies] : steps) {
        orderSoftContacts(*contacts, bodies, 2, kept);
        SoftContactOrder fresh;
        orderSoftContacts(*contacts, bodies, 1, fresh);
        expectValidOrder(*contacts, bodies, kept);
        expectSameOrder(kept, fresh);
    }
}

} // namespace
} // namespace tumble
