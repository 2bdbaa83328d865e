// The soft step's warm start (docs/physics/12-soft-step.md, (12.5)): each contact's last
// impulses, kept by its owner from one step to the next.
#pragma once

#include "body_slot.hpp"
#include "dynamics/soft_contact_solver.hpp"
#include "step/coupled_step.hpp"
#include "step/island_contacts.hpp"

#include <span>

namespace tumble {

/// Starts a contact's manifold from the impulses its owner kept for the same other side: each
/// point's normal impulse where a point of the same feature key was kept (else one within ten
/// contact tolerances of where it is), the friction impulse projected on the manifold's
/// tangents, and the twist impulse. A contact new to its owner starts from none.
void warmStartFromCache(const CoupledIsland& island, std::span<const BodySlot> slots,
                        const IslandContact& contact, SoftManifold& manifold, Real tolerance);

/// Keeps the contacts' impulses in their owners' caches, replacing the island's old ones; each
/// owner's contacts go to one of `threads`.
void storeSoftWarmStart(const CoupledIsland& island, std::span<BodySlot> slots,
                        std::span<const IslandContact> contacts,
                        std::span<const SoftContactResult> results, int threads);

} // namespace tumble
