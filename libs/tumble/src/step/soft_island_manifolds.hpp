// A soft island's manifolds at the start of a step: built from the narrow phase, or kept from
// the last step and started again (docs/physics/12-soft-step.md, (12.3), (12.5), (12.5b), (12.9)).
#pragma once

#include "step/step_context.hpp"
#include "tumble/math.hpp"

#include <cstddef>
#include <span>

namespace tumble {

struct BodySlot;
struct CoupledIsland;
struct SoftBuffers;

/// The island's contacts (12.1), their kept impulses matched (12.5), their colours, and their
/// manifolds: packed in `buffers.lanes` for a large island (12.9), the rest in
/// `buffers.manifolds`. Reads the bodies' start of the step from `buffers`.
void buildSoftManifolds(const CoupledIsland& island, std::span<BodySlot> slots,
                        const StepContext& context, Real dt, SoftBuffers& buffers);

/// (12.5b): every manifold kept in `buffers` started again from the bodies' velocities there.
void restartSoftManifolds(SoftBuffers& buffers, int threads);

/// The first manifold, in colour order, that is not packed in lanes: the overflow group's, or 0.
std::size_t firstUnpackedManifold(const SoftBuffers& buffers);

/// Fills `buffers.results` (softResultOf of each manifold, in colour order) from the lanes and
/// the manifolds not packed, for the warm-start store (12.5).
void collectSoftResults(SoftBuffers& buffers, int threads);

} // namespace tumble
