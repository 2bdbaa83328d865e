// Contacts in colour order (docs/physics/11-island-solver.md, (11.5c)).
#include "step/contact_colour_order.hpp"

#include "dynamics/constraint_colouring.hpp"
#include "dynamics/island_solver.hpp"
#include "parallel_for.hpp"

#include <numeric>

namespace tumble {

void orderContactsByColour(std::vector<IslandContact>& contacts, std::size_t solverBodies,
                           std::vector<IslandContact>& spare, int threads)
{
    std::size_t points = 0;
    for (const IslandContact& contact : contacts) {
        points += static_cast<std::size_t>(contact.manifold.pointCount);
    }
    if (points < kColouredSweepPoints) {
        return;
    }
    // a contact with no point makes no run of the sweeps: it takes no colour, and goes last
    std::vector<ProxyPair> runs;
    std::vector<std::uint32_t> withPoints;
    for (std::uint32_t index = 0; index < contacts.size(); ++index) {
        if (contacts[index].manifold.pointCount > 0) {
            runs.push_back({contacts[index].solverA, contacts[index].solverB});
            withPoints.push_back(index);
        }
    }
    // the static side is the last solver body
    std::vector<std::uint8_t> fixed(solverBodies, 0);
    fixed.back() = 1;
    const ConstraintColours colours = colourConstraints(runs, fixed, kMaxConstraintColours);
    const std::size_t coloured = colours.constraints.size();
    spare.resize(coloured);
    parallelFor(coloured, threads, [&](std::size_t k) {
        spare[k] = contacts[withPoints[colours.constraints[k]]];
    });
    for (const IslandContact& contact : contacts) {
        if (contact.manifold.pointCount == 0) {
            spare.push_back(contact);
        }
    }
    contacts.swap(spare);
}

} // namespace tumble
