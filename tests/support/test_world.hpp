// TestWorld: a World with the ground plane and helpers to simulate for a time and watch it.
#pragma once

#include "tumble/world.hpp"

#include <cmath>
#include <functional>

namespace tumble::testing {

/// Named tolerances, with why each value.
/// Quantities computed in closed form and by a few double operations.
inline constexpr Real kExact = 1e-12;
/// The handouts print six decimals; their matrices are compared at that precision.
inline constexpr Real kSixDecimals = 1e-6;

/// The handout cuboid: the default 2x2x2 cube scaled by (1, 3, 1).
inline BodyDef handoutCuboid(Real mass)
{
    BodyDef def;
    def.shape.size = Vec3(2.0, 6.0, 2.0);
    def.mass = mass;
    return def;
}

inline Real totalEnergy(const World& world, BodyId id)
{
    const Body& body = world.body(id);
    return body.kineticEnergy() + body.potentialEnergy(world.settings().gravity);
}

/// Steps `world` for `seconds` with fixed `dt` (rounded to whole steps), calling `afterStep`
/// after every step.
inline void simulate(World& world, Real seconds, Real dt,
                     const std::function<void(const World&)>& afterStep = {})
{
    const long long steps = std::llround(seconds / dt);
    for (long long i = 0; i < steps; ++i) {
        world.step(dt);
        if (afterStep) {
            afterStep(world);
        }
    }
}

/// A world with the default settings (gravity, exact integrator, sequential response) and the
/// ground plane y = 0.
inline World worldWithGround(const WorldSettings& settings = {})
{
    World world(settings);
    world.setGround(Plane{});
    return world;
}

} // namespace tumble::testing
