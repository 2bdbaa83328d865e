// The kinetic energy the work booking reads from a body's inertial frame
// (docs/physics/08-energy-ledger.md, (8.2)).
#include "dynamics/energy_booking.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble {
namespace {

// A 1 x 2 x 3 m cuboid of 6 kg turned 90 degrees about z: its body y axis lies along world -x,
// so a spin of 2 rad/s about world x is a spin about body y, whose moment is
// m (a^2 + c^2) / 12 = 6 (1 + 9) / 12 = 5 kg m^2 (about body x it would be 6.5). With 1 m/s
// along x: T = 6 * 1 / 2 + 5 * 4 / 2 = 13 J.
TEST(EnergyBooking, KineticEnergyTurnsTheSpinIntoTheBodyFrame)
{
    Body body;
    body.mass = 6.0;
    body.shape.size = Vec3(1.0, 2.0, 3.0);
    body.orientation = glm::angleAxis(0.5 * std::acos(-1.0), Vec3(0.0, 0.0, 1.0));
    const Vec3 linear(1.0, 0.0, 0.0);
    const Vec3 angular(2.0, 0.0, 0.0);
    EXPECT_NEAR(kineticEnergyWith(inertialFrameOf(body), linear, angular), 13.0, 1e-12);
    EXPECT_NEAR(kineticEnergyWith(body, linear, angular), 13.0, 1e-12);
}

} // namespace
} // namespace tumble
