// Picking: the ray through a pixel, the cuboid it enters, the nearest moving body.
#include "viewer/picking.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble::viewer {
namespace {

TEST(Picking, TheRayThroughTheCentreOfTheViewGoesToTheTarget)
{
    const OrbitCamera camera(glm::vec3(1.0f, 2.0f, 3.0f), 10.0f);
    const Ray ray = pixelRay(camera, glm::vec2(400.0f, 300.0f), glm::vec2(800.0f, 600.0f));
    const glm::vec3 toTarget = glm::normalize(camera.target() - camera.eye());
    EXPECT_NEAR(glm::dot(ray.direction, toTarget), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(ray.origin - camera.eye()), 0.0f, 1e-5f);
}

TEST(Picking, ARayEntersARotatedCuboidAtItsFace)
{
    World world;
    // a 2 m cube turned 45 degrees about y: along x its corner is sqrt(2) from the centre
    const BodyId id = world.createBody(BodyDef{.position = Vec3(5.0, 0.0, 0.0),
                                               .orientation = axisAngle(Vec3(0, 1, 0), 0.785398163397448)});
    const Ray ray{glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f)};
    const std::optional<float> hit = rayHitsCuboid(ray, world.body(id));
    ASSERT_TRUE(hit.has_value());
    EXPECT_NEAR(*hit, 5.0f - std::sqrt(2.0f), 1e-5f);
    // pointing away, or passing above, misses
    EXPECT_FALSE(rayHitsCuboid({glm::vec3(0.0f), glm::vec3(-1.0f, 0.0f, 0.0f)}, world.body(id)));
    EXPECT_FALSE(rayHitsCuboid({glm::vec3(0.0f, 1.5f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f)},
                               world.body(id)));
}

TEST(Picking, TheNearestMovingBodyIsPickedAndStaticGeometryIsNot)
{
    World world;
    const std::vector<BodyId> bodies{
        world.createBody(BodyDef{.position = Vec3(10.0, 0.0, 0.0)}),
        world.createBody(BodyDef{.position = Vec3(5.0, 0.0, 0.0)}),
        world.createBody(BodyDef{.motion = BodyMotion::Static, .position = Vec3(2.0, 0.0, 0.0)})};
    const Ray ray{glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f)};
    EXPECT_EQ(pickBody(ray, world, bodies), std::optional<std::size_t>(1));
    EXPECT_EQ(pickBody({glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f)}, world, bodies),
              std::nullopt);
}

} // namespace
} // namespace tumble::viewer
