// Impacts within an island reported as CollisionEvents, one per contact that an impact solve
// pushed on, naming both sides.
#pragma once

#include "body_slot.hpp"
#include "dynamics/contact_constraint.hpp"
#include "step/coupled_step.hpp"
#include "step/island_contacts.hpp"
#include "step/step_events.hpp"

#include <span>

namespace tumble {

/// Reports the impact of each contact with a point that approached faster than `impactSpeed` and
/// was pushed. The event's body is the moving side with more kinetic energy before; its normal points into that
/// body's side and its impulses are those acting on it. `kineticBefore` holds the island bodies'
/// kinetic energies before the solve.
void recordIslandImpacts(const CoupledIsland& island, std::span<const BodySlot> slots,
                         std::span<const IslandContact> contacts,
                         std::span<const ContactConstraint> impact,
                         std::span<const Real> kineticBefore, Real impactSpeed, Real time,
                         StepEvents& events);

} // namespace tumble
