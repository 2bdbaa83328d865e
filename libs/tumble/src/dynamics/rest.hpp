// Rest detection and sleeping (docs/physics/07-rest.md, (7.1)-(7.3)).
#pragma once

#include "body_slot.hpp"
#include "step/step_context.hpp"
#include "step/step_events.hpp"

#include <span>

namespace tumble {

/// After a step of dt: a body slow (7.1) and in contact for the settings' sleep time is at rest
/// since it became slow (7.2); it is reported with its face down (7.3) and, when sleeping is
/// allowed, put to sleep with its kinetic energy booked as removed at rest.
void updateRest(BodyId id, BodySlot& slot, const StepContext& context, Real dt,
                StepEvents& events);

/// The same for an island of touching bodies, which comes to rest and sleeps as a whole: its
/// bodies' slow time grows only while every one of them is slow and in contact (7.4).
void updateIslandRest(std::span<const std::uint32_t> bodies, std::span<BodySlot> slots,
                      const StepContext& context, Real dt, StepEvents& events);

} // namespace tumble
