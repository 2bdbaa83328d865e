// A box resting on a tilted static plane: the world of the slope tests (docs/physics/06-friction.md,
// (6.6)).
#pragma once

#include "tumble/world.hpp"

#include <cmath>
#include <numbers>

namespace tumble::testing {

struct Slope {
    World world;
    BodyId box{};
    /// Unit vector down the slope.
    Vec3 downhill{0.0};
};

/// A plane through the origin tilted by `degrees` about z (rising with x), and a box of mass 1,
/// width and depth `width`, height `height`, no bounce, resting on it at the origin.
inline Slope makeSlope(Real degrees, Real friction, Real width, Real height,
                       const WorldSettings& settings)
{
    Slope slope{World(settings)};
    const Real angle = degrees * std::numbers::pi / 180.0;
    const Vec3 normal(-std::sin(angle), std::cos(angle), 0.0);
    slope.world.addPlane(StaticPlane{.point = Vec3(0.0), .normal = normal});
    slope.downhill = Vec3(-std::cos(angle), -std::sin(angle), 0.0);
    slope.box = slope.world.createBody(
        BodyDef{.shape = Cuboid{Vec3(width, height, width)},
                .mass = 1.0,
                .position = 0.5 * height * normal,
                .orientation = axisAngle(Vec3(0, 0, 1), angle),
                .material = Material{.restitution = 0.0, .friction = friction}});
    return slope;
}

} // namespace tumble::testing
