// The soft step's rows built a block of manifolds at a time, in the lanes they are solved in
// (docs/physics/12-soft-step.md, (12.3), (12.9)). For dynamics/soft_lanes.cpp only.
#pragma once

#include "dynamics/soft_lane_rows.hpp"

#include <span>

namespace tumble::soft_rows {

/// prepareSoftRows (soft_rows.cpp) lane by lane, the same operations in the same order,
/// for a block whose anchors, centres, normal, tangents, inverse masses and points' `active`
/// are packed: each present point's effective mass and lever arm, the couplings, and the
/// friction and twist rows at the centres. An absent point keeps its empty rows (unit mass).
void prepareLaneRows(LaneBlock& block, std::span<const SoftBody> bodies);

} // namespace tumble::soft_rows
