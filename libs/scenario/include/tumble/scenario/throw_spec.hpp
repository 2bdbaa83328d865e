// ThrowSpec: the [throw] table of a scenario, the ranges a die's initial state is drawn from.
#pragma once

#include "tumble/math.hpp"

namespace tumble::scenario {

/// A closed interval [min, max] (min <= max) that a quantity is drawn from uniformly.
struct DrawRange {
    Real min = 0.0;
    Real max = 0.0;
};

/// How a throw's initial orientation is chosen.
enum class ThrowOrientation {
    /// Uniform over all rotations (Shoemake's method). The default.
    Random,
    /// The orientation the [[body]] gives, the same for every throw.
    Body,
};

/// The ranges of `tumble throw` (docs/scenario-format.md, docs/dice.md). Every default is the
/// one a scenario file gets when it omits the key.
struct ThrowSpec {
    /// Release height of the centre of mass above the ground, m. Default [0.5, 1.0].
    DrawRange height{0.5, 1.0};
    /// Horizontal speed, in a direction drawn uniformly, m/s. Default [0.5, 2.0].
    DrawRange speed{0.5, 2.0};
    /// Vertical velocity (up positive), m/s. Default [-1.0, 0.0].
    DrawRange verticalSpeed{-1.0, 0.0};
    /// Magnitude of the angular velocity, about an axis drawn uniformly on the sphere, rad/s.
    /// Default [5.0, 20.0].
    DrawRange angularSpeed{5.0, 20.0};
    /// Default ThrowOrientation::Random.
    ThrowOrientation orientation = ThrowOrientation::Random;
    /// A throw not at rest by this simulated time is unsettled, s. Default 20.
    Real maxTime = 20.0;
};

} // namespace tumble::scenario
