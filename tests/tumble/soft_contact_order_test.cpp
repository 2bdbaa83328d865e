// The soft step's contacts in colour order (docs/physics/12-soft-step.md, (12.9)): every contact
// once, no dynamic body twice in a colour, and the same tables whether they are made afresh or
// kept from the last step for the same contacts.
#include "step/soft_contact_order.hpp"

#include <gtest/gtest.h>

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
}

TEST(SoftContactOrder, ColoursEveryContactOnceAndNoBodyTwiceAColour)
{
    const std::vector<IslandContact> contacts = randomContacts(1, 40, 300);
    SoftContactOrder order;
    orderSoftContacts(contacts, 40, 1, order);
    expectValidOrder(contacts, 40, order);
    EXPECT_GT(order.colours.offsets.size(), 4u);
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
