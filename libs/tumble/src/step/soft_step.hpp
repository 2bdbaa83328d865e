// The soft step of an island (WorldSettings::solver = ContactSolver::Soft): one narrow phase a
// step with speculative points, then fixed sub-steps of one biased solve and one relax pass,
// and restitution at the end (docs/physics/12-soft-step.md).
#pragma once

#include "body_slot.hpp"
#include "step/coupled_step.hpp"
#include "step/step_context.hpp"
#include "step/step_events.hpp"

#include <span>

namespace tumble {

/// Advances the island's bodies by dt with the soft step. Writes only the slots of
/// `island.bodies`; its result does not depend on `context.threads`.
void advanceSoft(const CoupledIsland& island, std::span<BodySlot> slots,
                 const StepContext& context, Real dt, StepEvents& events);

} // namespace tumble
