// The order the soft step's passes take an island's contacts in: colour by colour
// (docs/physics/12-soft-step.md, (12.9); docs/physics/10-broad-phase.md, (10.5)).
#pragma once

#include "dynamics/constraint_colouring.hpp"
#include "dynamics/soft_contact_solver.hpp"
#include "step/island_contacts.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace tumble {

/// An island's contacts in colour order: the k-th manifold the passes take is contact
/// colourOrder[k], and contact i is the colourPosition[i]-th.
struct SoftContactOrder {
    /// Each contact's two solver bodies, in the contacts' order and in colour order.
    std::vector<ProxyPair> ends;
    std::vector<ProxyPair> colourEnds;
    std::vector<std::uint32_t> colourOrder;
    std::vector<std::uint32_t> colourPosition;
    SoftColours colours;
    /// Scratch: which solver bodies are static.
    std::vector<std::uint8_t> isStatic;
    /// The island size the tables were made for (none yet: the largest size), and the next
    /// step's ends, compared with `ends` before the tables are made again.
    std::size_t colouredBodies = static_cast<std::size_t>(-1);
    std::vector<ProxyPair> nextEnds;
};

/// (10.5): colours the contacts of an island of `bodyCount` dynamic bodies (the static solver
/// body is the next index) so that no colour moves a dynamic body twice, whatever the
/// `threads`; the tables are filled over the threads.
void orderSoftContacts(std::span<const IslandContact> contacts, std::size_t bodyCount,
                       int threads, SoftContactOrder& order);

} // namespace tumble
