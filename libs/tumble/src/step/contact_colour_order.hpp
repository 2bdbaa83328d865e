// The order of a large island's contacts: colour by colour, so that each colour's points lie
// together in memory for the sweeps (docs/physics/11-island-solver.md, (11.5c)).
#pragma once

#include "step/island_contacts.hpp"

#include <vector>

namespace tumble {

/// (11.5c): when the island has at least kColouredSweepPoints points, reorders its contacts so
/// that those of colour 0 come first, then colour 1 and so on, keeping their order within a
/// colour; the colours are those the coloured sweeps give the contacts' runs of points, so each
/// colour is one stretch of the constraints. `solverBodies` counts the island's solver bodies,
/// the static one (the last) included. `spare` is scratch space. The contacts are copied over
/// `threads` threads, each to its own place.
void orderContactsByColour(std::vector<IslandContact>& contacts, std::size_t solverBodies,
                           std::vector<IslandContact>& spare, int threads);

} // namespace tumble
