// The soft step's contacts colour by colour (docs/physics/12-soft-step.md, (12.9)).
#include "step/soft_contact_order.hpp"

#include "parallel_for.hpp"

#include <utility>

namespace tumble {

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
