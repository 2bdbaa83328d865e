// What the exact step builds from an island's contacts: one constraint per point, and the
// contacts grouped by the body that keeps their warm start (docs/physics/11-island-solver.md).
#pragma once

#include "dynamics/contact_constraint.hpp"
#include "step/coupled_step.hpp"
#include "step/island_contacts.hpp"
#include "step/owner_groups.hpp"

#include <span>
#include <vector>

namespace tumble {

/// The island's contacts grouped by the body that keeps their warm start (IslandContact::owner),
/// each group in the contacts' order, so that each owner's cache can be written on its own
/// thread as from one pass. The groups live in the calling thread's storage until its next call.
const OwnerGroups& contactsByOwner(std::span<const IslandContact> contacts, std::size_t bodies);

/// One constraint per contact point, with the geometry, material, tangent basis, Jacobian rows
/// and effective masses set (prepareConstraintGeometry, with the bodies' inverse masses and
/// inertias now; impulses zero); the contacts spread over `threads`, each writing its own
/// constraints.
void buildConstraints(std::span<IslandContact> contacts, std::span<const BodySlot> slots,
                      const CoupledIsland& island, std::vector<ContactConstraint>& constraints,
                      int threads = 1);

} // namespace tumble
