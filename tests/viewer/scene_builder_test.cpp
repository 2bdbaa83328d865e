#include "viewer/scene_builder.hpp"

#include "viewer/palette.hpp"

#include "tumble/world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace tumble::viewer {
namespace {

struct Scene {
    World world;
    std::vector<BodyId> bodies;
    std::vector<std::optional<CollisionEvent>> lastCollisions;
};

/// A cube resting face down on the ground, and a 2 x 6 x 2 block up in the air.
Scene restingCubeAndFlyingBlock()
{
    Scene scene;
    scene.world.setGround(Plane{});
    scene.bodies.push_back(scene.world.createBody({.position = {0.0, 1.0, 0.0}}));
    scene.bodies.push_back(scene.world.createBody({.shape = {.size = {2.0, 6.0, 2.0}},
                                                   .position = {5.0, 8.0, 0.0},
                                                   .angularVelocity = {0.0, 2.0, 0.0}}));
    scene.lastCollisions.resize(2);
    return scene;
}

TEST(SceneBuilder, OneCuboidPerBodyScaledToItsSize)
{
    Scene scene = restingCubeAndFlyingBlock();
    const SceneDrawList list =
        buildScene(scene.world, scene.bodies, scene.lastCollisions, ViewerSettings{}, 0.0f);
    ASSERT_EQ(list.cuboids.size(), 2u);
    const CuboidInstance& block = list.cuboids[1];
    EXPECT_EQ(block.centre, glm::vec3(5.0f, 8.0f, 0.0f));
    // the unit cube's +y face centre lands on the block's top
    const glm::vec4 top = block.model * glm::vec4(0.0f, 0.5f, 0.0f, 1.0f);
    EXPECT_FLOAT_EQ(top.y, 11.0f);
    EXPECT_NEAR(block.radius, 0.5f * std::sqrt(44.0f), 1e-5f);
    EXPECT_TRUE(list.cuboids[0].selected);
    EXPECT_FALSE(list.cuboids[1].selected);
    EXPECT_TRUE(list.gridIsGround);
    EXPECT_EQ(list.gridHeight, 0.0f);
}

TEST(SceneBuilder, ContactMarkersForTouchingVerticesAndTheirAverage)
{
    Scene scene = restingCubeAndFlyingBlock();
    const SceneDrawList list =
        buildScene(scene.world, scene.bodies, scene.lastCollisions, ViewerSettings{}, 0.0f);
    // the resting cube touches with a face: four vertices and their average
    ASSERT_EQ(list.markers.size(), 5u);
    EXPECT_EQ(list.markers.back().colour, palette::kContactAverage);
    EXPECT_NEAR(list.markers.back().position.x, 0.0f, 1e-5f);
    EXPECT_NEAR(list.markers.back().position.y, 0.0f, 1e-5f);

    ViewerSettings hidden;
    hidden.showContacts = false;
    EXPECT_TRUE(
        buildScene(scene.world, scene.bodies, scene.lastCollisions, hidden, 0.0f).markers.empty());
}

TEST(SceneBuilder, ImpulseArrowsStartAtTheCollisionsAveragePoint)
{
    Scene scene = restingCubeAndFlyingBlock();
    CollisionEvent collision;
    collision.manifold.pointCount = 1;
    collision.manifold.points[0].position = {1.0, 0.0, 2.0};
    collision.normalImpulse = {0.0, 10.0, 0.0};
    collision.frictionImpulse = {-2.0, 0.0, 0.0};
    scene.lastCollisions[0] = collision;
    ViewerSettings settings;
    settings.impulseScale = 0.1f;
    const SceneDrawList list =
        buildScene(scene.world, scene.bodies, scene.lastCollisions, settings, 0.0f);
    ASSERT_EQ(list.arrows.size(), 2u);
    EXPECT_EQ(list.arrows[0].from, glm::vec3(1.0f, 0.0f, 2.0f));
    EXPECT_EQ(list.arrows[0].to, glm::vec3(1.0f, 1.0f, 2.0f));
    EXPECT_EQ(list.arrows[0].colour, palette::kNormalImpulse);
    EXPECT_EQ(list.arrows[1].to, glm::vec3(0.8f, 0.0f, 2.0f));
    EXPECT_EQ(list.arrows[1].colour, palette::kFrictionImpulse);
}

TEST(SceneBuilder, AxesAndVectorsOnDemand)
{
    Scene scene = restingCubeAndFlyingBlock();
    ViewerSettings settings;
    settings.showContacts = false;
    EXPECT_TRUE(buildScene(scene.world, scene.bodies, scene.lastCollisions, settings, 0.0f)
                    .arrows.empty());

    settings.showAxes = true;
    settings.showAngularVelocity = true;
    settings.showAngularMomentum = true;
    settings.vectorScale = 0.5f;
    const SceneDrawList list =
        buildScene(scene.world, scene.bodies, scene.lastCollisions, settings, 0.0f);
    // three axes per body; w and L only for the spinning block
    ASSERT_EQ(list.arrows.size(), 8u);
    const auto spin = std::find_if(list.arrows.begin(), list.arrows.end(), [](const ArrowInstance& a) {
        return a.colour == palette::kAngularVelocity;
    });
    ASSERT_NE(spin, list.arrows.end());
    EXPECT_EQ(spin->from, glm::vec3(5.0f, 8.0f, 0.0f));
    EXPECT_EQ(spin->to, glm::vec3(5.0f, 9.0f, 0.0f));
}

TEST(SceneBuilder, SceneWithoutGroundGetsAReferenceGrid)
{
    World world;
    const std::vector<BodyId> bodies{world.createBody({})};
    const std::vector<std::optional<CollisionEvent>> none(1);
    const SceneDrawList list = buildScene(world, bodies, none, ViewerSettings{}, -4.0f);
    EXPECT_FALSE(list.gridIsGround);
    EXPECT_EQ(list.gridHeight, -4.0f);
    EXPECT_TRUE(list.markers.empty());
}

} // namespace
TEST(SceneBuilder, ContactMarkersShrinkInCrowdedScenesButNotBelowAThird)
{
    // issue 14, item 18: a hundred bodies' full-size dots hid the cuboids
    EXPECT_EQ(contactMarkerScale(1), 1.0f);
    EXPECT_EQ(contactMarkerScale(10), 1.0f);
    EXPECT_NEAR(contactMarkerScale(40), 0.5f, 1e-6f);
    EXPECT_EQ(contactMarkerScale(10000), kMinMarkerScale);
}

} // namespace tumble::viewer
