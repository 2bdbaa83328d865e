// The soft step's contacts colour by colour (docs/physics/12-soft-step.md, (12.9)).
#include "step/soft_contact_order.hpp"

#include "parallel_for.hpp"

#include <algorithm>
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
    ConstraintColours colours =
        colourConstraints(order.ends, order.isStatic, kMaxConstraintColours);
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
