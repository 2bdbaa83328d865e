// The exact step of a body whose only obstacle is the ground: sub-steps cut at each impact by
// the time of impact, exact rotation, and the energy ledger (docs/physics/README.md, "One step").
#pragma once

#include "body_slot.hpp"
#include "step/step_context.hpp"
#include "step/step_events.hpp"

namespace tumble {

/// Advances the body by dt: in flight when it cannot reach the ground within the step (4.7),
/// (4.7a); otherwise in sub-steps of detection, impact, resting contact, time of impact,
/// positions and corrections.
void advanceSolitary(BodyId id, BodySlot& slot, const StepContext& context, Real dt,
                     StepEvents& events);

} // namespace tumble
