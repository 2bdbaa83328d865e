// The soft step's contacts colour by colour (docs/physics/12-soft-step.md, (12.9)).
#include "step/soft_contact_order.hpp"

#include "parallel_for.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace tumble {

namespace {

/// Orders each colour's contacts by the lower index of their dynamic bodies. A colour's
/// contacts share no dynamic body, so their order within it changes no bit (12.9); in this
/// order the share of a colour each thread takes (its first or last blocks) holds about the
/// same bodies colour after colour, where the colouring's order (the contacts' pairs, the
/// ground's last) handed one body to the threads in turn.
void placeBodiesTogether(std::span<const ProxyPair> ends, std::size_t bodyCount,
                         ConstraintColours& colours)
{
    const auto keyOf = [&](std::uint32_t contact) {
        const ProxyPair& pair = ends[contact];
        return std::min(pair.a < bodyCount ? pair.a : std::uint32_t(-1),
                        pair.b < bodyCount ? pair.b : std::uint32_t(-1));
    };
    for (std::uint32_t c = 0; c < colours.colourCount; ++c) {
        const auto first = colours.constraints.begin() + colours.offsets[c];
        const auto last = colours.constraints.begin() + colours.offsets[c + 1];
        std::stable_sort(first, last, [&](std::uint32_t x, std::uint32_t y) {
            return keyOf(x) < keyOf(y);
        });
    }
}

/// An island of this many contacts or more is split in two halves of its bodies (12.9).
constexpr std::size_t kHalvedContacts = 1024;

/// (12.9): where the island's bodies (in their order in it) split into two halves that hold
/// as many contacts each: the first body of the second half. A contact is within the first
/// half if its higher dynamic body is before the split, within the second if its lower one is
/// not.
std::size_t balancedSplit(std::span<const ProxyPair> ends, std::size_t bodyCount)
{
    std::vector<std::uint32_t> highest(bodyCount, 0);
    std::vector<std::uint32_t> lowest(bodyCount, 0);
    for (const ProxyPair& pair : ends) {
        const bool aMoves = pair.a < bodyCount;
        const bool bMoves = pair.b < bodyCount;
        ++highest[aMoves && bMoves ? std::max(pair.a, pair.b) : (aMoves ? pair.a : pair.b)];
        ++lowest[aMoves && bMoves ? std::min(pair.a, pair.b) : (aMoves ? pair.a : pair.b)];
    }
    // before body m: the contacts within [0, m) and within [m, bodyCount)
    std::size_t first = 0;
    std::size_t second = ends.size();
    std::size_t best = 0;
    std::size_t bestGap = second;
    for (std::size_t m = 0; m <= bodyCount; ++m) {
        const std::size_t gap = first > second ? first - second : second - first;
        if (gap < bestGap) {
            bestGap = gap;
            best = m;
        }
        if (m < bodyCount) {
            first += highest[m];
            second -= lowest[m];
        }
    }
    return best;
}

/// (12.9): the contacts within the first half of the island's bodies (balancedSplit), those
/// within the second half, and those across, each group coloured on its own (10.5) and in that
/// order; the three groups' overflows together last. `halves` gets the split and the first two
/// groups' colour counts.
ConstraintColours colourInHalves(std::span<const ProxyPair> ends,
                                 std::span<const std::uint8_t> isStatic, std::size_t bodyCount,
                                 SoftColours& halves)
{
    const std::size_t middle = balancedSplit(ends, bodyCount);
    halves.halfSplit = static_cast<std::uint32_t>(middle);
    // the half of a body, none for the static one
    const auto halfOf = [&](std::uint32_t body) {
        return body >= bodyCount ? -1 : (body < middle ? 0 : 1);
    };
    std::array<std::vector<std::uint32_t>, 3> members;
    for (std::uint32_t k = 0; k < ends.size(); ++k) {
        const int a = halfOf(ends[k].a);
        const int b = halfOf(ends[k].b);
        const int group = a < 0 ? b : (b < 0 || a == b ? a : 2);
        members[static_cast<std::size_t>(group)].push_back(k);
    }
    ConstraintColours result;
    result.offsets.assign(1, 0);
    result.constraints.reserve(ends.size());
    std::vector<std::uint32_t> overflow;
    std::vector<ProxyPair> groupEnds;
    for (std::size_t group = 0; group < members.size(); ++group) {
        const std::vector<std::uint32_t>& contacts = members[group];
        groupEnds.resize(contacts.size());
        for (std::size_t i = 0; i < contacts.size(); ++i) {
            groupEnds[i] = ends[contacts[i]];
        }
        const ConstraintColours part =
            colourConstraints(groupEnds, isStatic, kMaxConstraintColours);
        for (std::uint32_t c = 0; c < part.colourCount; ++c) {
            for (const std::uint32_t i : part.colour(c)) {
                result.constraints.push_back(contacts[i]);
            }
            result.offsets.push_back(static_cast<std::uint32_t>(result.constraints.size()));
        }
        for (const std::uint32_t i : part.overflow()) {
            overflow.push_back(contacts[i]);
        }
        if (group < 2) {
            halves.halfColours[group] = part.colourCount;
        }
    }
    result.colourCount = static_cast<std::uint32_t>(result.offsets.size() - 1);
    result.constraints.insert(result.constraints.end(), overflow.begin(), overflow.end());
    result.offsets.push_back(static_cast<std::uint32_t>(result.constraints.size()));
    return result;
}

} // namespace

void orderSoftContacts(std::span<const IslandContact> contacts, std::size_t bodyCount,
                       int threads, SoftContactOrder& order)
{
    // (10.5): the same colours whatever the threads, so every pass sweeps the manifolds in the
    // same order and a large colour can be split over the threads (11.5c)
    order.nextEnds.resize(contacts.size());
    parallelFor(contacts.size(), threads, [&](std::size_t k) {
        order.nextEnds[k] = ProxyPair{contacts[k].solverA, contacts[k].solverB};
    });
    // the colours depend on the ends and the body count alone: a settled island's are last
    // step's
    if (order.colouredBodies == bodyCount && order.nextEnds == order.ends) {
        return;
    }
    std::swap(order.ends, order.nextEnds);
    order.colouredBodies = bodyCount;
    order.isStatic.assign(bodyCount + 1, 0);
    order.isStatic[bodyCount] = 1;
    order.colours.halfColours = {0, 0};
    order.colours.halfSplit = 0;
    ConstraintColours colours =
        contacts.size() >= kHalvedContacts
            ? colourInHalves(order.ends, order.isStatic, bodyCount, order.colours)
            : colourConstraints(order.ends, order.isStatic, kMaxConstraintColours);
    placeBodiesTogether(order.ends, bodyCount, colours);
    order.colourEnds.resize(contacts.size());
    order.colourPosition.resize(contacts.size());
    parallelFor(contacts.size(), threads, [&](std::size_t k) {
        const std::uint32_t contact = colours.constraints[k];
        order.colourEnds[k] = order.ends[contact];
        order.colourPosition[contact] = static_cast<std::uint32_t>(k);
    });
    order.colourOrder = std::move(colours.constraints);
    order.colours.offsets = std::move(colours.offsets);
}

} // namespace tumble
