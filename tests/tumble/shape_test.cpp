// Cuboid mass properties and geometry (docs/physics/01-inertia.md).
#include "tumble/shape.hpp"

#include "support/glm_printers.hpp"
#include "support/test_world.hpp"

#include <gtest/gtest.h>

namespace tumble {
namespace {

using testing::kExact;
using testing::near;

TEST(Shape, HandoutCuboidOfMassTwoHasInverseInertiaFromPartThree)
{
    // (1.1) with m = 2, (w, h, d) = (2, 6, 2): I0 = diag(40/6, 8/6, 40/6), so
    // I0^-1 = diag(0.15, 0.75, 0.15).
    EXPECT_TRUE(near(cuboidInverseInertiaDiagonal(2.0, Vec3(2, 6, 2)), Vec3(0.15, 0.75, 0.15), kExact));
}

TEST(Shape, HandoutCuboidOfMassOneHasInverseInertiaFromPartTwo)
{
    EXPECT_TRUE(near(cuboidInverseInertiaDiagonal(1.0, Vec3(2, 6, 2)), Vec3(0.3, 1.5, 0.3), kExact));
}

TEST(Shape, InertiaOfAGeneralCuboidFollowsTheTextbookFormula)
{
    // 1 x 2 x 3 box of 6 kg: I = 6/12 (4 + 9, 1 + 9, 1 + 4) = (6.5, 5, 2.5).
    EXPECT_TRUE(near(cuboidInertiaDiagonal(6.0, Vec3(1, 2, 3)), Vec3(6.5, 5.0, 2.5), kExact));
}

TEST(Shape, VerticesAreTheEightSignPatternsOfTheHalfExtents)
{
    const auto vertices = cuboidVertices(Vec3(1, 3, 1));
    EXPECT_TRUE(near(vertices[0], Vec3(-1, -3, -1), 0.0));
    EXPECT_TRUE(near(vertices[3], Vec3(1, 3, -1), 0.0));
    EXPECT_TRUE(near(vertices[7], Vec3(1, 3, 1), 0.0));
    Vec3 sum(0.0);
    for (const Vec3& v : vertices) {
        sum += v;
    }
    EXPECT_TRUE(near(sum, Vec3(0.0), 0.0));
}

TEST(Shape, FaceAlongNamesTheFaceWhoseNormalPointsThatWay)
{
    const Quat identity(1, 0, 0, 0);
    EXPECT_EQ(faceAlong(identity, Vec3(0, -1, 0)), CuboidFace::MinusY);
    // Rolled 90 degrees about z: the body's +x axis points up, so -x faces the ground.
    const Quat rolled = axisAngle(Vec3(0, 0, 1), glm::radians(90.0));
    EXPECT_EQ(faceAlong(rolled, Vec3(0, -1, 0)), CuboidFace::MinusX);
    EXPECT_STREQ(faceName(faceAlong(rolled, Vec3(0, 1, 0))), "+x");
}

} // namespace
} // namespace tumble
