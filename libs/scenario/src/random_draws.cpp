// Uniform directions and rotations from RandomDraws (docs/scenario-format.md, [[spawn]]).
#include "tumble/scenario/random_draws.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tumble::scenario {

Vec3 RandomDraws::direction()
{
    // The area of a spherical zone is proportional to its height, so z uniform in [-1, 1] and
    // an azimuth uniform in [0, 2 pi) are uniform on the sphere.
    const Real z = uniform(-1.0, 1.0);
    const Real azimuth = 2.0 * std::numbers::pi * unit();
    const Real radius = std::sqrt(std::max(0.0, 1.0 - z * z));
    return Vec3(radius * std::cos(azimuth), z, radius * std::sin(azimuth));
}

Quat RandomDraws::rotation()
{
    // Shoemake: with u1, u2, u3 uniform, (sqrt(1-u1) sin 2pi u2, sqrt(1-u1) cos 2pi u2,
    // sqrt(u1) sin 2pi u3, sqrt(u1) cos 2pi u3) is uniform on the unit 3-sphere, and a uniform
    // unit quaternion is a uniform rotation. It is unit to rounding; bodies normalise it.
    const Real u1 = unit();
    const Real angle2 = 2.0 * std::numbers::pi * unit();
    const Real angle3 = 2.0 * std::numbers::pi * unit();
    const Real a = std::sqrt(1.0 - u1);
    const Real b = std::sqrt(u1);
    return Quat(b * std::cos(angle3), a * std::sin(angle2), a * std::cos(angle2), b * std::sin(angle3));
}

} // namespace tumble::scenario
