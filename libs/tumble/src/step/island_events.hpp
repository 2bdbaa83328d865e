// Impacts and contact solves within an island, reported as CollisionEvents and ContactRecords
// that name both sides.
#pragma once

#include "body_slot.hpp"
#include "dynamics/contact_constraint.hpp"
#include "step/coupled_step.hpp"
#include "step/island_contacts.hpp"
#include "step/step_events.hpp"

#include <span>

namespace tumble {

/// Reports the impact of each contact with a point that approached faster than `impactSpeed` and
/// was pushed. The event's body is the moving side with more kinetic energy before; its normal
/// points into that body's side and its impulses and velocities are those of that body (relative
/// to the other side). `kineticBefore` holds the island bodies' kinetic energies before the
/// solve, `bodies` the solver bodies after it.
void recordIslandImpacts(const CoupledIsland& island, std::span<const BodySlot> slots,
                         std::span<const IslandContact> contacts,
                         std::span<const ContactConstraint> impact,
                         std::span<const SolverBody> bodies, std::span<const Real> kineticBefore,
                         Real impactSpeed, Real time, StepEvents& events);

/// For the contact ledger (WorldSettings::recordContacts): one ContactRecord per contact with a
/// point in contact or pushed, named as the impacts are.
void recordIslandContacts(ContactPhase phase, const CoupledIsland& island,
                          std::span<const BodySlot> slots, std::span<const IslandContact> contacts,
                          std::span<const ContactConstraint> constraints,
                          std::span<const SolverBody> bodies, std::span<const Real> kinetic,
                          Real tolerance, Real time, StepEvents& events);

} // namespace tumble
