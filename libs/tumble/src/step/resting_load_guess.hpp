// A first guess of the normal impulses of contacts that have no warm start yet: the weight each
// body carries, passed down to what supports it (docs/physics/11-island-solver.md, (11.13)).
#pragma once

#include "body_slot.hpp"
#include "dynamics/contact_constraint.hpp"
#include "step/coupled_step.hpp"
#include "step/island_contacts.hpp"

#include <span>
#include <vector>

namespace tumble {

/// Sets the normal impulse of each constraint marked in `guess` (in contact, with no warm start)
/// to its share of the weight its upper body carries over tau: bodies are visited from the
/// highest down; each passes its own weight plus what rests on it to the contacts below it, as
/// the least-norm normal forces that carry it (a contact's force in proportion to how upright
/// its normal is), equally among a contact's points, and on to the body below. The sweeps then only correct the guess; a column of boxes starts from its exact answer.
void guessRestingImpulses(const CoupledIsland& island, std::span<const BodySlot> slots,
                          std::span<const IslandContact> contacts,
                          std::span<ContactConstraint> constraints,
                          const std::vector<std::uint8_t>& guess, const Vec3& gravity, Real tau);

} // namespace tumble
