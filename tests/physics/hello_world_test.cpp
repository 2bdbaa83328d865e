// The hello-world usage of tumble, as the README shows it: a ground, a cube, a few seconds.
#include "tumble/tumble.hpp"

#include <gtest/gtest.h>

TEST(HelloWorld, CubeDroppedOnTheGroundRestsAtItsHalfHeight)
{
    tumble::World world;
    world.setGround(tumble::Plane{.height = 0.0});
    const tumble::BodyId cube = world.createBody({
        .shape = tumble::Cuboid{.size = {1.0, 1.0, 1.0}},
        .mass = 1.0,
        .position = {0.0, 2.0, 0.0},
    });
    for (int i = 0; i < 5 * 240; ++i) {
        world.step(1.0 / 240.0);
    }
    const tumble::Body& body = world.body(cube);
    EXPECT_NEAR(body.position.y, 0.5, 1e-9);
    EXPECT_LT(glm::length(body.linearVelocity), 1e-9);
    EXPECT_TRUE(body.asleep);
}
