// The handouts' step (ContactResponse::Average) for a body alone with the ground
// (docs/physics/05-normal-impulse.md, (5.7)).
#pragma once

#include "body_slot.hpp"
#include "step/step_context.hpp"
#include "step/step_events.hpp"

namespace tumble {

/// A whole free step, then, if a vertex touches the ground, the body lifted out and one impulse
/// at the average touching vertex.
void advanceHandoutStep(BodyId id, BodySlot& slot, const StepContext& context, Real dt,
                        StepEvents& events);

} // namespace tumble
