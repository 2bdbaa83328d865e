// The length of a vector read from a scenario, for range checks and messages.
#pragma once

#include "tumble/math.hpp"

#include <algorithm>
#include <cmath>

namespace tumble::scenario::detail {

/// |v| for any finite v: the components are scaled by the largest before squaring, so the squares
/// cannot overflow (glm::length([0, 1e300, 0]) is inf) and the result, at most sqrt(3) times the
/// largest component, is finite.
inline Real vectorLength(const Vec3& v)
{
    const Real largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (!(largest > 0.0) || !std::isfinite(largest)) {
        return largest;
    }
    return largest * glm::length(v / largest);
}

} // namespace tumble::scenario::detail
