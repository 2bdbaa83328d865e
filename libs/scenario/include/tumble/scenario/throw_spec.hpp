// ThrowSpec: the [throw] table of a scenario, the ranges a die's initial state is drawn from.
#pragma once

#include "tumble/math.hpp"

#include <numbers>
#include <optional>

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

/// Where the dice of a throw start.
enum class ThrowRelease {
    /// Every die draws its own release point and velocity. The default.
    Each,
    /// The dice leave one hand: one release point and velocity for the throw, each die within
    /// `clusterRadius` of that point.
    Cluster,
};

/// An axis-aligned box the release points are drawn from, world coordinates, m.
struct ThrowRegion {
    Vec3 min{0.0};
    Vec3 max{0.0};
};

/// The ranges of `tumble throw` (docs/scenario-format.md, docs/dice.md). Every default is the
/// one a scenario file gets when it omits the key.
struct ThrowSpec {
    /// Release height of the centre of mass above the ground, m. Default [0.5, 1.0].
    DrawRange height{0.5, 1.0};
    /// Horizontal speed, in a direction drawn uniformly from `heading`, m/s. Default [0.5, 2.0].
    DrawRange speed{0.5, 2.0};
    /// Direction of the horizontal velocity, radians from +x toward +z (the file gives degrees).
    /// Default [0, 2 pi]: every direction.
    DrawRange heading{0.0, 2.0 * std::numbers::pi};
    /// Vertical velocity (up positive), m/s. Default [-1.0, 0.0].
    DrawRange verticalSpeed{-1.0, 0.0};
    /// Magnitude of the angular velocity, about an axis drawn uniformly on the sphere, rad/s.
    /// Default [5.0, 20.0].
    DrawRange angularSpeed{5.0, 20.0};
    /// Default ThrowOrientation::Random.
    ThrowOrientation orientation = ThrowOrientation::Random;
    /// A throw not at rest by this simulated time is unsettled, s. Default 20.
    Real maxTime = 20.0;
    /// Default ThrowRelease::Each.
    ThrowRelease release = ThrowRelease::Each;
    /// With ThrowRelease::Cluster, the largest distance of a die's centre from the hand's release
    /// point, m. Default 0.03.
    Real clusterRadius = 0.03;
    /// Release points drawn uniformly in this box; none: straight above the origin at a drawn
    /// `height` over the ground (the single-die model).
    std::optional<ThrowRegion> region;
};

} // namespace tumble::scenario
