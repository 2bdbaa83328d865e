// The contact between two shapes as narrow-phase routines report it: one normal, up to 4 points.
#pragma once

#include "tumble/math.hpp"

#include <array>
#include <cstdint>

namespace tumble {

/// One point of a contact between shape A and shape B.
struct PairContactPoint {
    Vec3 position{0.0};     // world frame, m: midway between the two surfaces at this point
    Real separation = 0.0;  // signed gap along the normal, m (negative: penetration)
    std::uint32_t id = 0;   // key of the pair of features that made this point; stable while the same features touch, unique within a manifold
};

/// Contact between two shapes: at most 4 points sharing one normal.
struct PairManifold {
    Vec3 normal{0.0, 1.0, 0.0};   // unit, world frame, pointing from A towards B
    std::array<PairContactPoint, 4> points{};
    int pointCount = 0;
};

} // namespace tumble
