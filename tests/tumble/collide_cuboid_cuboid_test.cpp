// Contact between two cuboids: face-face, edge-edge and vertex-face configurations with answers
// worked out by hand, and properties over random poses (docs/physics/09-box-box.md).
#include "collision/collide_cuboid_cuboid.hpp"

#include "support/glm_printers.hpp"
#include "tumble/shape.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <vector>

namespace tumble {
namespace {

using testing::near;

/// Positions and separations from a few dozen double operations on values of order 1.
constexpr Real kCoordinates = 1e-12;
constexpr Real kMargin = 5e-3;
const Vec3 kUp(0.0, 1.0, 0.0);
const Quat kIdentity(1.0, 0.0, 0.0, 0.0);
const Real kSqrt2 = std::numbers::sqrt2;

bool idsUnique(const PairManifold& manifold)
{
    std::set<std::uint32_t> ids;
    for (int i = 0; i < manifold.pointCount; ++i) {
        ids.insert(manifold.points[i].id);
    }
    return static_cast<int>(ids.size()) == manifold.pointCount;
}

/// Is there a point at `position` (any order)?
bool hasPointAt(const PairManifold& manifold, const Vec3& position)
{
    for (int i = 0; i < manifold.pointCount; ++i) {
        if (testing::maxDifference(manifold.points[i].position, position) <= kCoordinates) {
            return true;
        }
    }
    return false;
}

/// Area of the convex polygon through the points, seen along `normal` (points sorted by angle).
Real polygonArea(const PairManifold& manifold)
{
    Vec3 centre(0.0);
    for (int i = 0; i < manifold.pointCount; ++i) {
        centre += manifold.points[i].position / Real(manifold.pointCount);
    }
    Vec3 t1;
    Vec3 t2;
    orthonormalBasis(manifold.normal, t1, t2);
    std::vector<std::pair<Real, Vec3>> byAngle;
    for (int i = 0; i < manifold.pointCount; ++i) {
        const Vec3 r = manifold.points[i].position - centre;
        byAngle.emplace_back(std::atan2(glm::dot(r, t2), glm::dot(r, t1)), r);
    }
    std::sort(byAngle.begin(), byAngle.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    Real twiceArea = 0.0;
    for (std::size_t i = 0; i < byAngle.size(); ++i) {
        const Vec3& a = byAngle[i].second;
        const Vec3& b = byAngle[(i + 1) % byAngle.size()].second;
        twiceArea += glm::dot(glm::cross(a, b), manifold.normal);
    }
    return 0.5 * twiceArea;
}

/// The unit cube B (half extent 1) resting on the unit cube A at the origin, lowest point of B
/// `gap` above A's top face (negative: below), B turned by `turn`.
Transform cubeOnCube(const Quat& turn, Real gap, Real dx = 0.0, Real dz = 0.0)
{
    Real lowest = 0.0;
    for (const Vec3& vertex : cuboidVertices(Vec3(1.0))) {
        lowest = std::min(lowest, (turn * vertex).y);
    }
    return Transform{Vec3(dx, 1.0 + gap - lowest, dz), turn};
}

TEST(CollideCuboidCuboid, CubeOnCubeFaceToFaceGivesTheCornersOfTheOverlapSquare)
{
    // B's bottom face spans x in [-0.5, 1.5], z in [-0.75, 1.25]; A's top face [-1, 1]^2. The
    // overlap is x in [-0.5, 1], z in [-0.75, 1]; B's face is 0.01 below A's, so the points are
    // 0.005 below y = 1.
    const Transform a{Vec3(0.0), kIdentity};
    const Transform b = cubeOnCube(kIdentity, -0.01, 0.5, 0.25);
    const PairManifold manifold = collideCuboids(a, Vec3(1.0), b, Vec3(1.0), kMargin);
    ASSERT_EQ(manifold.pointCount, 4);
    EXPECT_TRUE(near(manifold.normal, kUp, 0.0));
    EXPECT_TRUE(hasPointAt(manifold, Vec3(-0.5, 0.995, -0.75)));
    EXPECT_TRUE(hasPointAt(manifold, Vec3(1.0, 0.995, -0.75)));
    EXPECT_TRUE(hasPointAt(manifold, Vec3(1.0, 0.995, 1.0)));
    EXPECT_TRUE(hasPointAt(manifold, Vec3(-0.5, 0.995, 1.0)));
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(manifold.points[i].separation, -0.01, kCoordinates);
    }
    EXPECT_TRUE(idsUnique(manifold));
}

TEST(CollideCuboidCuboid, SmallCubeOnBigBoxKeepsTheFourCornersOfItsFace)
{
    // A's top face is y = 0.5; B (half extent 0.25) sinks 0.001 into it around (1, -0.5).
    const Transform a{Vec3(0.0), kIdentity};
    const Transform b{Vec3(1.0, 0.75 - 0.001, -0.5), kIdentity};
    const PairManifold manifold = collideCuboids(a, Vec3(3.0, 0.5, 2.0), b, Vec3(0.25), kMargin);
    ASSERT_EQ(manifold.pointCount, 4);
    EXPECT_TRUE(near(manifold.normal, kUp, 0.0));
    for (const Real x : {0.75, 1.25}) {
        for (const Real z : {-0.75, -0.25}) {
            EXPECT_TRUE(hasPointAt(manifold, Vec3(x, 0.5 - 0.0005, z))) << x << ", " << z;
        }
    }
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(manifold.points[i].separation, -0.001, kCoordinates);
    }
    EXPECT_TRUE(idsUnique(manifold));
}

TEST(CollideCuboidCuboid, CubeTurnedFortyFiveDegreesKeepsFourOfTheOctagonsCorners)
{
    // The overlap of [-1, 1]^2 and the same square turned 45 degrees is the regular octagon
    // |x|, |z| <= 1, |x| + |z| <= sqrt 2, of area 8 (sqrt 2 - 1) and circumradius^2 4 - 2 sqrt 2.
    // The best inscribed quadrilateral is the square on alternate corners, 2 R^2: 1/sqrt 2 of it.
    const Transform a{Vec3(0.0), kIdentity};
    const Transform b = cubeOnCube(axisAngle(kUp, std::numbers::pi / 4), -0.01);
    const PairManifold manifold = collideCuboids(a, Vec3(1.0), b, Vec3(1.0), kMargin);
    ASSERT_EQ(manifold.pointCount, 4);
    EXPECT_TRUE(near(manifold.normal, kUp, 0.0));
    EXPECT_TRUE(idsUnique(manifold));
    for (int i = 0; i < 4; ++i) {
        const Vec3& p = manifold.points[i].position;
        EXPECT_NEAR(manifold.points[i].separation, -0.01, kCoordinates);
        EXPECT_NEAR(p.y, 0.995, kCoordinates);
        // An octagon corner lies on both squares' edges.
        EXPECT_NEAR(std::max(std::abs(p.x), std::abs(p.z)), 1.0, 1e-9);
        EXPECT_NEAR(std::abs(p.x) + std::abs(p.z), kSqrt2, 1e-9);
    }
    const Real octagon = 8.0 * (kSqrt2 - 1.0);
    EXPECT_GE(polygonArea(manifold), 0.70 * octagon);
    EXPECT_NEAR(polygonArea(manifold), 2.0 * (4.0 - 2.0 * kSqrt2), 1e-9);
}

/// A cube resting on a cube, turned by `yaw` about y, then its bottom face tilted by `angle`
/// about `axis`; its lowest point 0.001 below A's top plane. The margin covers the height of its
/// highest bottom corner. The kept points span at least `minArea`.
void expectFaceContactWhenTilted(const Vec3& axis, Real angle, Real yaw, Real minArea)
{
    const Real margin = 0.05;
    const Transform a{Vec3(0.0), kIdentity};
    const Quat turn = axisAngle(glm::normalize(axis), angle) * axisAngle(kUp, yaw);
    const Transform b = cubeOnCube(turn, -0.001);
    const PairManifold manifold = collideCuboids(a, Vec3(1.0), b, Vec3(1.0), margin);
    ASSERT_EQ(manifold.pointCount, 4);
    // A face of either box: the normal is up or B's tilted face normal.
    EXPECT_GE(manifold.normal.y, std::cos(angle) - 1e-15);
    EXPECT_TRUE(idsUnique(manifold));
    Real deepest = margin;
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(manifold.points[i].id >> 15, 0u) << "an edge-edge id";
        deepest = std::min(deepest, manifold.points[i].separation);
    }
    EXPECT_GE(polygonArea(manifold), minArea);
    if (yaw == 0.0) {
        // B's lowest corner is over A's top face, so A's face is the least penetration and A is
        // preferred over B's face; that corner is the deepest point. (Turned 45 degrees the
        // lowest corner overhangs A and either face may be the reference.)
        EXPECT_TRUE(near(manifold.normal, kUp, 0.0));
        EXPECT_NEAR(deepest, -0.001, 1e-9);
    }
}

TEST(CollideCuboidCuboid, NearlyParallelFacesGiveAFaceContactNotAnEdge)
{
    // Square on square: nearly the whole 2 x 2 face (the tilt moves B's corners by at most
    // 2 angle sideways). Turned 45 degrees: the octagon's best quadrilateral, 1/sqrt 2 of
    // 8 (sqrt 2 - 1) (see above), less the same sideways motion. Turned 45 degrees, edge axes
    // such as a_x x b_x lie a tilt's fraction off the vertical and, unbiased, beat the face by
    // rounding or by the tilt (9.5).
    for (const Real angle : {1e-6, 1e-4, 1e-2}) {
        SCOPED_TRACE(angle);
        for (const Vec3& axis : {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0.3, 0, -1)}) {
            SCOPED_TRACE(::testing::PrintToString(axis));
            expectFaceContactWhenTilted(axis, angle, 0.0, 4.0 * (1.0 - 4.0 * angle));
            expectFaceContactWhenTilted(axis, angle, std::numbers::pi / 4,
                                        (4.0 - 2.0 * kSqrt2) * 2.0 * (1.0 - 4.0 * angle));
        }
    }
}

/// A: the unit cube turned 45 degrees about z, its top edge along z at x = 0, y = sqrt 2.
/// B: the unit cube turned 45 degrees about x, its bottom edge along x at z = -0.2, 0.01 lower.
void crossedEdges(Transform& a, Transform& b)
{
    a = Transform{Vec3(0.0), axisAngle(Vec3(0, 0, 1), std::numbers::pi / 4)};
    b = Transform{Vec3(0.3, 2.0 * kSqrt2 - 0.01, -0.2),
                  axisAngle(Vec3(1, 0, 0), std::numbers::pi / 4)};
}

TEST(CollideCuboidCuboid, CrossingEdgesGiveOnePointBetweenThem)
{
    Transform a;
    Transform b;
    crossedEdges(a, b);
    const PairManifold manifold = collideCuboids(a, Vec3(1.0), b, Vec3(1.0), kMargin);
    ASSERT_EQ(manifold.pointCount, 1);
    EXPECT_TRUE(near(manifold.normal, kUp, kCoordinates));
    // The edges cross above (0, -0.2): A's at y = sqrt 2, B's 0.01 lower; the point is midway.
    EXPECT_TRUE(near(manifold.points[0].position, Vec3(0.0, kSqrt2 - 0.005, -0.2), kCoordinates));
    EXPECT_NEAR(manifold.points[0].separation, -0.01, kCoordinates);
    // Edge-edge tag; A's edge along z on +x, +y (index 4 2 + 1 + 2); B's along x on -y, +z (2).
    EXPECT_EQ(manifold.points[0].id, (1u << 15) | 11u | (2u << 4));
}

TEST(CollideCuboidCuboid, CubeOnItsCornerGivesOnePoint)
{
    // Turn B's body diagonal (1, 1, 1) onto +y: vertex (-1, -1, -1) is sqrt 3 below its centre.
    const Vec3 diagonal = glm::normalize(Vec3(1, 1, 1));
    const Quat turn = axisAngle(glm::normalize(glm::cross(diagonal, kUp)),
                                std::acos(glm::dot(diagonal, kUp)));
    const Transform a{Vec3(0.0), kIdentity};
    const Transform b{Vec3(0.3, 0.5 - 0.002 + std::sqrt(3.0), -0.1), turn};
    const PairManifold manifold = collideCuboids(a, Vec3(2.0, 0.5, 2.0), b, Vec3(1.0), kMargin);
    ASSERT_EQ(manifold.pointCount, 1);
    EXPECT_TRUE(near(manifold.normal, kUp, 0.0));
    EXPECT_TRUE(near(manifold.points[0].position, Vec3(0.3, 0.499, -0.1), kCoordinates));
    EXPECT_NEAR(manifold.points[0].separation, -0.002, kCoordinates);
}

TEST(CollideCuboidCuboid, SeparatedByMoreThanTheMarginGivesNothing)
{
    const Transform a{Vec3(0.0), kIdentity};
    EXPECT_EQ(collideCuboids(a, Vec3(1.0), cubeOnCube(kIdentity, 2.0 * kMargin), Vec3(1.0),
                             kMargin).pointCount, 0);
    // Apart along an edge axis only: the crossed edges 0.02 apart.
    Transform edgeA;
    Transform edgeB;
    crossedEdges(edgeA, edgeB);
    edgeB.position.y += 0.03;
    EXPECT_EQ(collideCuboids(edgeA, Vec3(1.0), edgeB, Vec3(1.0), kMargin).pointCount, 0);
}

TEST(CollideCuboidCuboid, WithinTheMarginGivesSpeculativePoints)
{
    const Transform a{Vec3(0.0), kIdentity};
    const Transform b = cubeOnCube(kIdentity, 0.002, 0.5, 0.25);
    const PairManifold manifold = collideCuboids(a, Vec3(1.0), b, Vec3(1.0), kMargin);
    ASSERT_EQ(manifold.pointCount, 4);
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(manifold.points[i].separation, 0.002, kCoordinates);
        EXPECT_NEAR(manifold.points[i].position.y, 1.001, kCoordinates);
    }
    EXPECT_TRUE(hasPointAt(manifold, Vec3(1.0, 1.001, 1.0)));
}

/// collideCuboids(b, a) has the opposite normal and the same points as collideCuboids(a, b).
void expectSwapSymmetric(const Transform& a, const Vec3& extentsA, const Transform& b,
                         const Vec3& extentsB)
{
    const PairManifold ab = collideCuboids(a, extentsA, b, extentsB, kMargin);
    const PairManifold ba = collideCuboids(b, extentsB, a, extentsA, kMargin);
    ASSERT_GT(ab.pointCount, 0);
    ASSERT_EQ(ab.pointCount, ba.pointCount);
    EXPECT_TRUE(near(ba.normal, -ab.normal, kCoordinates));
    for (int i = 0; i < ab.pointCount; ++i) {
        EXPECT_TRUE(hasPointAt(ba, ab.points[i].position)) << i;
        EXPECT_NEAR(ba.points[i].separation, ab.points[i].separation, kCoordinates);
    }
}

TEST(CollideCuboidCuboid, SwappingTheBoxesFlipsTheNormalAndKeepsThePoints)
{
    const Transform a{Vec3(0.0), kIdentity};
    expectSwapSymmetric(a, Vec3(1.0), cubeOnCube(kIdentity, -0.01, 0.5, 0.25), Vec3(1.0));
    expectSwapSymmetric(a, Vec3(3.0, 0.5, 2.0), Transform{Vec3(1.0, 0.749, -0.5), kIdentity},
                        Vec3(0.25));
    Transform edgeA;
    Transform edgeB;
    crossedEdges(edgeA, edgeB);
    expectSwapSymmetric(edgeA, Vec3(1.0), edgeB, Vec3(1.0));
}

/// A generic resting pose: B tilted 0.03 rad about a skew axis, overhanging A's corner.
Transform tiltedOverhangingCube()
{
    return cubeOnCube(axisAngle(glm::normalize(Vec3(0.3, 0.2, 1.0)), 0.03), -0.004, 0.7, 0.4);
}

TEST(CollideCuboidCuboid, IdsAreStableUnderATinyTranslation)
{
    const Transform a{Vec3(0.0), kIdentity};
    Transform b = tiltedOverhangingCube();
    const PairManifold before = collideCuboids(a, Vec3(1.0), b, Vec3(1.0), 0.05);
    b.position += Vec3(1e-6, -1e-6, 1e-6);
    const PairManifold after = collideCuboids(a, Vec3(1.0), b, Vec3(1.0), 0.05);
    ASSERT_EQ(before.pointCount, 4);
    ASSERT_EQ(after.pointCount, 4);
    EXPECT_TRUE(idsUnique(before));
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(after.points[i].id, before.points[i].id) << i;
    }
    Transform edgeA;
    Transform edgeB;
    crossedEdges(edgeA, edgeB);
    const std::uint32_t edgeId = collideCuboids(edgeA, Vec3(1.0), edgeB, Vec3(1.0), kMargin)
                                     .points[0].id;
    edgeB.position += Vec3(1e-6, 1e-6, -1e-6);
    EXPECT_EQ(collideCuboids(edgeA, Vec3(1.0), edgeB, Vec3(1.0), kMargin).points[0].id, edgeId);
}

TEST(CollideCuboidCuboid, EqualCubesStackedKeepTheirCornersUnderRoundingLevelTurns)
{
    // (9.7): the incident corners lie on the reference face's edges; turns and shifts of 1e-15
    // put them a rounding error in or out. Each pose still gives the four corners of the face,
    // with the names of the aligned stack, so warm starting finds them from step to step.
    const Transform a{Vec3(0.0), kIdentity};
    const PairManifold aligned = collideCuboids(a, Vec3(1.0), cubeOnCube(kIdentity, 0.0), Vec3(1.0),
                                                kMargin);
    ASSERT_EQ(aligned.pointCount, 4);
    std::mt19937_64 random(15);
    std::uniform_real_distribution<Real> unit(-1.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const Vec3 axis = glm::normalize(Vec3(unit(random), unit(random), unit(random)));
        Transform b = cubeOnCube(axisAngle(axis, 1e-15 * unit(random)), 0.0);
        b.position += 1e-15 * Vec3(unit(random), unit(random), unit(random));
        const PairManifold manifold = collideCuboids(a, Vec3(1.0), b, Vec3(1.0), kMargin);
        ASSERT_EQ(manifold.pointCount, 4) << "trial " << trial;
        for (int i = 0; i < 4; ++i) {
            EXPECT_TRUE(hasPointAt(manifold, aligned.points[i].position)) << "trial " << trial;
            EXPECT_EQ(manifold.points[i].id, aligned.points[i].id) << "trial " << trial;
        }
    }
}

TEST(CollideCuboidCuboid, TranslatingBothBoxesMovesThePointsOnly)
{
    const Vec3 shift(1000.0, 0.0, 0.0);
    const Transform a{Vec3(0.0), kIdentity};
    const Transform b = tiltedOverhangingCube();
    const PairManifold here = collideCuboids(a, Vec3(1.0), b, Vec3(1.0), 0.05);
    const PairManifold there = collideCuboids(Transform{a.position + shift, a.orientation},
                                              Vec3(1.0),
                                              Transform{b.position + shift, b.orientation},
                                              Vec3(1.0), 0.05);
    ASSERT_EQ(there.pointCount, here.pointCount);
    EXPECT_TRUE(near(there.normal, here.normal, kCoordinates));
    for (int i = 0; i < here.pointCount; ++i) {
        // Coordinates near 1000 carry rounding of 1000 * 2^-52, about 2e-13 each.
        EXPECT_TRUE(near(there.points[i].position, here.points[i].position + shift, 1e-10));
        EXPECT_NEAR(there.points[i].separation, here.points[i].separation, 1e-10);
        EXPECT_EQ(there.points[i].id, here.points[i].id);
    }
}


/// A rotation drawn uniformly (Shoemake, "Uniform random rotations", Graphics Gems III).
Quat randomRotation(std::mt19937_64& random)
{
    std::uniform_real_distribution<Real> unit(0.0, 1.0);
    const Real u1 = unit(random);
    const Real u2 = 2.0 * std::numbers::pi * unit(random);
    const Real u3 = 2.0 * std::numbers::pi * unit(random);
    const Real a = std::sqrt(1.0 - u1);
    const Real b = std::sqrt(u1);
    return Quat(b * std::cos(u3), a * std::sin(u2), a * std::cos(u2), b * std::sin(u3));
}

/// Is `point` within the box's slabs widened by `tolerance`?
bool insideSlabs(const Transform& pose, const Vec3& halfExtents, const Vec3& point,
                 Real tolerance)
{
    const Vec3 local = glm::abs(glm::conjugate(pose.orientation) * (point - pose.position));
    return glm::all(glm::lessThanEqual(local, halfExtents + Vec3(tolerance)));
}

/// Does a vertex of box `a` lie inside box `b` by more than `depth`?
bool vertexInside(const Transform& a, const Vec3& extentsA, const Transform& b,
                  const Vec3& extentsB, Real depth)
{
    for (const Vec3& vertex : cuboidVertices(extentsA)) {
        if (insideSlabs(b, extentsB, a.position + a.orientation * vertex, -depth)) {
            return true;
        }
    }
    return false;
}

TEST(CollideCuboidCuboid, RandomPosesGivePointsInsideBothBoxes)
{
    constexpr Real margin = 0.01;
    std::mt19937_64 random(20240917);
    std::uniform_real_distribution<Real> unit(0.0, 1.0);
    const auto extents = [&] {
        return Vec3(0.1 + 1.9 * unit(random), 0.1 + 1.9 * unit(random), 0.1 + 1.9 * unit(random));
    };
    int withPoints = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        SCOPED_TRACE(trial);
        const Vec3 extentsA = extents();
        const Vec3 extentsB = extents();
        const Transform a{Vec3(10.0 * unit(random) - 5.0, 10.0 * unit(random) - 5.0, 0.0),
                          randomRotation(random)};
        // Centres apart by up to 1.2 times the sum of the half diagonals, in a uniform direction.
        const Real reach = glm::length(extentsA) + glm::length(extentsB);
        const Real distance = 1.2 * reach * unit(random);
        const Vec3 direction = randomRotation(random) * kUp;
        const Transform b{a.position + distance * direction, randomRotation(random)};
        const PairManifold manifold = collideCuboids(a, extentsA, b, extentsB, margin);
        ASSERT_GE(manifold.pointCount, 0);
        ASSERT_LE(manifold.pointCount, 4);
        if (distance > reach + margin) {
            EXPECT_EQ(manifold.pointCount, 0);
            continue;
        }
        if (vertexInside(a, extentsA, b, extentsB, 1e-6) ||
            vertexInside(b, extentsB, a, extentsA, 1e-6)) {
            EXPECT_GT(manifold.pointCount, 0) << "overlapping boxes without a contact";
        }
        if (manifold.pointCount == 0) {
            continue;
        }
        ++withPoints;
        EXPECT_NEAR(glm::length(manifold.normal), 1.0, 1e-12);
        EXPECT_TRUE(idsUnique(manifold));
        for (int i = 0; i < manifold.pointCount; ++i) {
            const PairContactPoint& point = manifold.points[i];
            EXPECT_LE(point.separation, margin);
            const Real tolerance = 1e-9 + std::abs(point.separation);
            EXPECT_TRUE(insideSlabs(a, extentsA, point.position, tolerance)) << i;
            EXPECT_TRUE(insideSlabs(b, extentsB, point.position, tolerance)) << i;
        }
    }
    // The draw reaches contacts often enough for the checks to mean something.
    EXPECT_GT(withPoints, 1000);
}

TEST(CollideCuboidCuboid, RandomNearlyLevelStacksGetFaceContacts)
{
    // B rests on A's top face, turned about y at random and tilted by up to 0.05 rad about a
    // horizontal axis, its lowest corner at -0.01..0.002 from A's top plane. The margin 0.5
    // exceeds every bottom-face height spread (at most 2 |e_B| sin 0.05 < 0.35), so every clipped
    // point is kept. Where that corner is over A's top face, A's face normal is the least
    // penetration: a face contact. Where it hangs beyond A's edge, the least penetration may be
    // an edge pair; one edge point is then right only if the edges cross, not nearly parallel.
    constexpr Real maxTilt = 0.05;
    std::mt19937_64 random(7);
    std::uniform_real_distribution<Real> unit(0.0, 1.0);
    const auto extents = [&] {
        return Vec3(0.2 + 1.8 * unit(random), 0.2 + 1.8 * unit(random), 0.2 + 1.8 * unit(random));
    };
    int overTheFace = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        SCOPED_TRACE(trial);
        const Vec3 extentsA = extents();
        const Vec3 extentsB = extents();
        const Real heading = 2.0 * std::numbers::pi * unit(random);
        const Quat turn = axisAngle(Vec3(std::cos(heading), 0.0, std::sin(heading)),
                                    maxTilt * unit(random)) *
                          axisAngle(kUp, 2.0 * std::numbers::pi * unit(random));
        Vec3 lowest(0.0);
        for (const Vec3& vertex : cuboidVertices(extentsB)) {
            lowest = (turn * vertex).y < lowest.y ? turn * vertex : lowest;
        }
        const Real gap = 0.012 * unit(random) - 0.01;
        const Vec3 centre((2.0 * unit(random) - 1.0) * extentsA.x, extentsA.y + gap - lowest.y,
                          (2.0 * unit(random) - 1.0) * extentsA.z);
        const Transform a{Vec3(0.0), kIdentity};
        const PairManifold manifold =
            collideCuboids(a, extentsA, Transform{centre, turn}, extentsB, 0.5);
        ASSERT_GE(manifold.pointCount, 1);
        const Vec3 corner = centre + lowest;
        if (std::abs(corner.x) < extentsA.x - 0.01 && std::abs(corner.z) < extentsA.z - 0.01) {
            ++overTheFace;
            EXPECT_GE(manifold.pointCount, 3);
            EXPECT_TRUE(near(manifold.normal, kUp, 0.0));
        } else if (manifold.points[0].id >> 15 != 0u) {
            // Edge index / 4 is the box axis the edge runs along; A's axes are the world's.
            const Vec3 edgeA = Mat3(1.0)[(manifold.points[0].id & 15u) / 4];
            const Vec3 edgeB = glm::mat3_cast(turn)[((manifold.points[0].id >> 4) & 15u) / 4];
            EXPECT_GE(glm::length(glm::cross(edgeA, edgeB)), std::sin(glm::radians(10.0)));
        }
    }
    EXPECT_GT(overTheFace, 500);
}

bool sameManifold(const PairManifold& a, const PairManifold& b)
{
    if (a.pointCount != b.pointCount || (a.pointCount > 0 && a.normal != b.normal)) {
        return false;
    }
    for (int i = 0; i < a.pointCount; ++i) {
        if (a.points[i].position != b.points[i].position ||
            a.points[i].separation != b.points[i].separation || a.points[i].id != b.points[i].id) {
            return false;
        }
    }
    return true;
}

TEST(CollideCuboidCuboid, GeometryFoundAtOneMarginGivesTheManifoldOfEveryMarginItDecides)
{
    // (9.11): the margin only stops the axis search and picks points, so a geometry that decides
    // a margin gives exactly collideCuboids' manifold at it.
    std::mt19937_64 random(20261125);
    std::uniform_real_distribution<Real> unit(0.0, 1.0);
    int decided = 0;
    int undecided = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        SCOPED_TRACE(trial);
        const Vec3 extentsA(0.2 + unit(random), 0.2 + unit(random), 0.2 + unit(random));
        const Vec3 extentsB(0.2 + unit(random), 0.2 + unit(random), 0.2 + unit(random));
        const Transform a{Vec3(0.0), randomRotation(random)};
        const Real reach = glm::length(extentsA) + glm::length(extentsB);
        const Transform b{reach * unit(random) * (randomRotation(random) * kUp),
                          randomRotation(random)};
        const Real searched = 0.1 * unit(random);
        const CuboidPairGeometry geometry =
            findCuboidPairGeometry(cuboidFrame(a, extentsA), cuboidFrame(b, extentsB), searched);
        for (const Real margin : {0.0, 1e-3, 0.01, 0.05, 0.1, 0.5}) {
            if (!decidesMargin(geometry, margin)) {
                // only a search stopped at an axis beyond its margin leaves a larger one open
                EXPECT_FALSE(geometry.complete);
                EXPECT_LE(geometry.largestSeparation, margin);
                ++undecided;
                continue;
            }
            ++decided;
            EXPECT_TRUE(sameManifold(manifoldWithin(geometry, margin),
                                     collideCuboids(a, extentsA, b, extentsB, margin)))
                << "margin " << margin;
        }
    }
    EXPECT_GT(decided, 1000);
    EXPECT_GT(undecided, 100);
}

TEST(CollideCuboidCuboid, GeometryKeepsPointsBeyondTheSearchMargin)
{
    // B's face is 0.01 above A's: no points within 5e-3, four within 0.02, from one geometry
    const CuboidPairGeometry geometry =
        findCuboidPairGeometry(cuboidFrame({Vec3(0.0), kIdentity}, Vec3(1.0)),
                               cuboidFrame(cubeOnCube(kIdentity, 0.01), Vec3(1.0)), 0.02);
    ASSERT_TRUE(geometry.complete);
    EXPECT_NEAR(geometry.largestSeparation, 0.01, kCoordinates);
    EXPECT_EQ(manifoldWithin(geometry, kMargin).pointCount, 0);
    EXPECT_EQ(manifoldWithin(geometry, 0.02).pointCount, 4);
}

} // namespace
} // namespace tumble
