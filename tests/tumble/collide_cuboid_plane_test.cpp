// Detection of the cuboid vertices touching the ground: vertex (1), edge (2), face (4)
// (docs/physics/04-detection.md, (4.1)-(4.2)).
#include "collision/collide_cuboid_plane.hpp"

#include "support/glm_printers.hpp"
#include "support/test_world.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tumble {
namespace {

using testing::near;

constexpr Real kTolerance = 1e-4;
/// Vertex coordinates after a rotation and a translation: a few roundings of order 1e-16.
constexpr Real kCoordinates = 1e-12;

TEST(CollideCuboidPlane, UprightHandoutCuboidTouchesWithAFace)
{
    const Transform pose{Vec3(0, 3, 0), Quat(1, 0, 0, 0)};
    const ContactManifold contacts = collideCuboidPlane(pose, Vec3(1, 3, 1), Plane{}, kTolerance);
    ASSERT_EQ(contacts.pointCount, 4);
    EXPECT_EQ(contacts.feature(), ContactFeature::Face);
    EXPECT_TRUE(near(contacts.points[0].position, Vec3(-1, 0, -1), kCoordinates));
    EXPECT_TRUE(near(contacts.points[1].position, Vec3(1, 0, -1), kCoordinates));
    EXPECT_TRUE(near(contacts.points[2].position, Vec3(-1, 0, 1), kCoordinates));
    EXPECT_TRUE(near(contacts.points[3].position, Vec3(1, 0, 1), kCoordinates));
    EXPECT_TRUE(near(contacts.averagePoint(), Vec3(0, 0, 0), kCoordinates));
}

TEST(CollideCuboidPlane, CubeTurnedFortyFiveDegreesAboutZRestsOnAnEdge)
{
    // The edge x = y = -1 of the cube ends at height sqrt(2) - sqrt(2) = 0, at x' = 0.
    const Transform pose{Vec3(2, std::sqrt(2.0), 0), axisAngle(Vec3(0, 0, 1), glm::radians(45.0))};
    const ContactManifold contacts = collideCuboidPlane(pose, Vec3(1), Plane{}, kTolerance);
    ASSERT_EQ(contacts.pointCount, 2);
    EXPECT_EQ(contacts.feature(), ContactFeature::Edge);
    EXPECT_TRUE(near(contacts.points[0].position, Vec3(2, 0, -1), kCoordinates));
    EXPECT_TRUE(near(contacts.points[1].position, Vec3(2, 0, 1), kCoordinates));
    EXPECT_TRUE(near(contacts.averagePoint(), Vec3(2, 0, 0), kCoordinates));
}

TEST(CollideCuboidPlane, CubeWithItsDiagonalVerticalRestsOnAVertex)
{
    // Turn the body diagonal (1, 1, 1) onto +y: vertex (-1, -1, -1) is then sqrt(3) below the
    // centre, straight down.
    const Vec3 diagonal = glm::normalize(Vec3(1, 1, 1));
    const Vec3 up(0, 1, 0);
    const Quat turn = axisAngle(glm::normalize(glm::cross(diagonal, up)),
                                std::acos(glm::dot(diagonal, up)));
    const Transform pose{Vec3(0.5, std::sqrt(3.0), -0.25), turn};
    const ContactManifold contacts = collideCuboidPlane(pose, Vec3(1), Plane{}, kTolerance);
    ASSERT_EQ(contacts.pointCount, 1);
    EXPECT_EQ(contacts.feature(), ContactFeature::Vertex);
    EXPECT_EQ(contacts.points[0].vertex, 0);
    EXPECT_TRUE(near(contacts.points[0].position, Vec3(0.5, 0, -0.25), kCoordinates));
    EXPECT_TRUE(near(contacts.averagePoint(), Vec3(0.5, 0, -0.25), kCoordinates));
}

TEST(CollideCuboidPlane, PenetrationIsTheDepthBelowThePlane)
{
    const Transform pose{Vec3(0, 2.75, 0), Quat(1, 0, 0, 0)};
    const ContactManifold contacts =
        collideCuboidPlane(pose, Vec3(1, 3, 1), Plane{.height = 0.5}, kTolerance);
    ASSERT_EQ(contacts.pointCount, 4);
    EXPECT_NEAR(contacts.maxPenetration(), 0.75, 1e-15);
    EXPECT_NEAR(contacts.points[2].position.y, -0.25, 1e-15);
}

TEST(CollideCuboidPlane, OnlyVerticesWithinTheToleranceTouch)
{
    const Transform near{Vec3(0, 1 + 0.5 * kTolerance, 0), Quat(1, 0, 0, 0)};
    EXPECT_EQ(collideCuboidPlane(near, Vec3(1), Plane{}, kTolerance).pointCount, 4);
    const Transform above{Vec3(0, 1 + 2.0 * kTolerance, 0), Quat(1, 0, 0, 0)};
    EXPECT_EQ(collideCuboidPlane(above, Vec3(1), Plane{}, kTolerance).pointCount, 0);
    EXPECT_EQ(collideCuboidPlane(above, Vec3(1), Plane{}, kTolerance).feature(),
              ContactFeature::None);
}

TEST(CollideCuboidPlane, LowestVertexHeightIsSignedDistance)
{
    const Transform pose{Vec3(0, 0.5, 0), Quat(1, 0, 0, 0)};
    EXPECT_NEAR(lowestVertexHeight(pose, Vec3(1), Plane{}), -0.5, 1e-15);
}

} // namespace
} // namespace tumble
