// The incident face clipping against the world-space form of (9.7) (tests/support/
// direct_face_clipping.hpp): clipping in the reference face's frame must keep the same points
// in the same order, with the same ids (9.9), positions and separations to rounding, on random,
// nearly aligned, exactly aligned and pyramid-stacked pairs (docs/physics/09-box-box.md).
#include "collision/cuboid_face_clipping.hpp"

#include "support/direct_face_clipping.hpp"
#include "support/glm_printers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <utility>

namespace tumble {
namespace {

/// Positions and separations come from a few dozen double operations on coordinates of the
/// size of the boxes and their distance from the origin.
constexpr Real kClipRounding = 1e-12;
/// A crossing divides its distances' rounding by the sine of the angle between the clipped edge
/// and the plane: below this sine the tolerance grows as 1 / sine.
constexpr Real kWellConditionedSine = 1e-2;

Real boxSize(const CuboidFrame& a, const CuboidFrame& b)
{
    return std::max({a.halfExtents.x, a.halfExtents.y, a.halfExtents.z, b.halfExtents.x,
                     b.halfExtents.y, b.halfExtents.z});
}

/// The size of the coordinates a position is computed from: the boxes and their distance from
/// the origin.
Real coordinateSize(const CuboidFrame& a, const CuboidFrame& b)
{
    return boxSize(a, b) + std::max(glm::length(a.centre), glm::length(b.centre));
}

/// What the comparisons met, to show that the cases reach every branch.
struct Tally {
    std::array<int, kMaxClippedPoints + 1> byCount{};
    int droppedByMargin = 0;
    int notClearCut = 0;
};

/// clipIncidentFace agrees with the direct form: the same points in the same order with the
/// same ids, positions and separations to rounding; when a decision of the direct form lay
/// within rounding of its threshold, only on the points both kept.
void expectSameClipping(const CuboidFrame& reference, int referenceFace,
                        const CuboidFrame& incident, Real margin, Tally& tally)
{
    for (const bool referenceIsB : {false, true}) {
        const testing::DirectClipping expected = testing::directClipIncidentFace(
            reference, referenceFace, incident, referenceIsB, margin);
        const ClippedPoints actual =
            clipIncidentFace(reference, referenceFace, incident, referenceIsB, margin);
        const Real size = coordinateSize(reference, incident);
        const Real tolerance = kClipRounding * size *
                               std::max(1.0, kWellConditionedSine / expected.crossingSine);
        if (expected.closestDecision <= kClipRounding * size) {
            ++tally.notClearCut;
            continue;
        }
        const ClippedPoints& points = expected.clipped;
        ASSERT_EQ(actual.count, points.count) << "reference face " << referenceFace;
        ++tally.byCount[points.count];
        if (margin < std::numeric_limits<Real>::infinity()) {
            tally.droppedByMargin +=
                clipIncidentFace(reference, referenceFace, incident, referenceIsB,
                                 std::numeric_limits<Real>::infinity())
                    .count > points.count;
        }
        for (int i = 0; i < points.count; ++i) {
            EXPECT_EQ(actual.points[i].id, points.points[i].id) << "point " << i;
            EXPECT_TRUE(testing::near(actual.points[i].position, points.points[i].position,
                                      tolerance))
                << "point " << i;
            EXPECT_NEAR(actual.points[i].separation, points.points[i].separation, tolerance)
                << "point " << i;
        }
    }
}

Quat randomOrientation(std::mt19937& random)
{
    std::normal_distribution<Real> gaussian;
    const Real w = gaussian(random);
    const Real x = gaussian(random);
    const Real y = gaussian(random);
    const Real z = gaussian(random);
    return glm::normalize(Quat(w, x, y, z));
}

/// Half extents of a box 0.1 to 3 m on a side.
Vec3 randomExtents(std::mt19937& random)
{
    std::uniform_real_distribution<Real> halfSide(0.05, 1.5);
    const Real x = halfSide(random);
    const Real y = halfSide(random);
    return Vec3(x, y, halfSide(random));
}

/// A turn of 0 to `largest` rad about a random axis.
Quat tilt(std::mt19937& random, Real largest)
{
    std::uniform_real_distribution<Real> angle(0.0, largest);
    const Vec3 axis = Vec3(randomOrientation(random) * Vec3(1, 0, 0));
    return glm::angleAxis(angle(random), glm::normalize(axis));
}

/// `incident`'s axes along `reference`'s: exactly (signed permutation `frame` of them, so every
/// a_i . b_j is 0 or +-1 bit for bit), or by a quarter-turn quaternion (to rounding).
CuboidFrame alignedWith(const CuboidFrame& reference, int frame, const Vec3& extents)
{
    const std::array<int, 3> order =
        std::array<std::array<int, 3>, 3>{{{0, 1, 2}, {1, 2, 0}, {2, 0, 1}}}[frame % 3];
    const Real s0 = (frame / 3) % 2 == 0 ? 1.0 : -1.0;
    const Real s1 = (frame / 6) % 2 == 0 ? 1.0 : -1.0;
    CuboidFrame incident{Vec3(0.0), {}, extents};
    incident.axes[0] = s0 * reference.axes[order[0]];
    incident.axes[1] = s1 * reference.axes[order[1]];
    incident.axes[2] = s0 * s1 * reference.axes[order[2]];
    return incident;
}

/// Moves `incident` so that its incident face lies on `referenceFace`, its centre `aside` along
/// the side axes (a_j1, a_j2) from the reference face's centre and `gap` out along its normal.
void placeOnFace(const CuboidFrame& reference, int referenceFace, CuboidFrame& incident,
                 const Vec3& aside, Real gap)
{
    const Vec3 normal = faceNormal(reference, referenceFace);
    const int axis = faceAxis(referenceFace);
    const int incidentFace = incidentFaceIndex(incident, normal);
    const int incidentAxis = faceAxis(incidentFace);
    incident.centre = reference.centre +
                      (reference.halfExtents[axis] + gap) * normal +
                      aside.x * reference.axes[(axis + 1) % 3] +
                      aside.y * reference.axes[(axis + 2) % 3] -
                      faceSign(incidentFace) * incident.halfExtents[incidentAxis] *
                          incident.axes[incidentAxis];
}

/// How the incident box is turned against the reference box.
enum class Turn { Random, Tilted, Exact, QuarterTurns, AboutTheNormal };

TEST(CuboidFaceClipping, RandomFacePairsGetThePointsOfTheWorldSpaceForm)
{
    // Incident faces from far inside the reference face to just overlapping its rim, from
    // 0.1 m inside to 0.05 m off it, so that the margins keep some of the points.
    std::mt19937 random(9007);
    std::uniform_real_distribution<Real> unit(-1.0, 1.0);
    std::uniform_real_distribution<Real> gapShare(-0.1, 0.02);
    std::uniform_int_distribution<int> faceChoice(0, 5);
    std::uniform_int_distribution<int> frameChoice(0, 11);
    const std::array<Real, 3> margins{0.0, 0.01, std::numeric_limits<Real>::infinity()};
    std::uniform_real_distribution<Real> angle(0.0, 2.0 * std::numbers::pi);
    const std::array<Turn, 5> turns{Turn::Random, Turn::Tilted, Turn::Exact, Turn::QuarterTurns,
                                    Turn::AboutTheNormal};
    Tally tally;
    for (int n = 0; n < 5000; ++n) {
        const Vec3 where(5.0 * unit(random), 5.0 * unit(random), 5.0 * unit(random));
        const CuboidFrame reference =
            cuboidFrame({where, randomOrientation(random)}, randomExtents(random));
        const Turn turn = turns[n % 5];
        const int referenceFace = faceChoice(random);
        const int axis = faceAxis(referenceFace);
        // Turned about the normal: about as wide as the reference face, to cut its 4 corners.
        const Vec3 extents = turn == Turn::AboutTheNormal
                                 ? reference.halfExtents * (1.0 + 0.1 * unit(random))
                                 : randomExtents(random);
        CuboidFrame incident = cuboidFrame({Vec3(0.0), randomOrientation(random)}, extents);
        if (turn == Turn::Tilted) {
            const Quat base = glm::quat_cast(
                Mat3(reference.axes[0], reference.axes[1], reference.axes[2]));
            incident = cuboidFrame({Vec3(0.0), base * tilt(random, 0.05)}, extents);
        } else if (turn == Turn::Exact) {
            incident = alignedWith(reference, frameChoice(random), extents);
        } else if (turn == Turn::QuarterTurns) {
            const Quat base = glm::quat_cast(
                Mat3(reference.axes[0], reference.axes[1], reference.axes[2]));
            const std::array<Vec3, 3> kAxes{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
            const int quarters = frameChoice(random);
            const Quat quarter =
                glm::angleAxis(0.5 * std::numbers::pi * (quarters % 4), kAxes[quarters / 4]);
            incident = cuboidFrame({Vec3(0.0), base * quarter}, extents);
        } else if (turn == Turn::AboutTheNormal) {
            // Any angle about the reference normal, then tilted: octagons at about 45 degrees.
            const Quat base = glm::quat_cast(
                Mat3(reference.axes[0], reference.axes[1], reference.axes[2]));
            Vec3 normal(0.0);
            normal[axis] = 1.0;
            incident = cuboidFrame(
                {Vec3(0.0), base * glm::angleAxis(angle(random), normal) * tilt(random, 0.05)},
                extents);
        }
        const Real reach = (turn == Turn::AboutTheNormal ? 0.05 : 1.2) * glm::length(extents);
        const Vec3 aside((reference.halfExtents[(axis + 1) % 3] + reach) * unit(random),
                         (reference.halfExtents[(axis + 2) % 3] + reach) * unit(random), 0.0);
        placeOnFace(reference, referenceFace, incident, aside,
                    gapShare(random) * glm::length(extents));
        expectSameClipping(reference, referenceFace, incident, margins[(n / 5) % 3], tally);
        if (::testing::Test::HasFatalFailure()) {
            return;
        }
    }
    // Every count of points from none to eight, margins that drop points, and decisions clear-cut.
    for (int count = 0; count <= kMaxClippedPoints; ++count) {
        EXPECT_GT(tally.byCount[count], 0) << count << " points";
    }
    EXPECT_GT(tally.droppedByMargin, 100);
    EXPECT_LT(tally.notClearCut, 10);
}

TEST(CuboidFaceClipping, StackedEqualBoxesKeepTheCornersOnTheSidePlanes)
{
    // As in a pyramid: equal boxes with parallel axes (exactly, or turned by up to 1e-10 rad),
    // face to face, the upper one flush with the lower one or shifted by half or a whole side,
    // each corner within 1e-12 of the box size of a side plane (or of the face's centre line).
    std::mt19937 random(1240);
    std::uniform_real_distribution<Real> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> faceChoice(0, 5);
    std::uniform_int_distribution<int> shiftChoice(-4, 4);
    const std::array<Real, 3> margins{0.0, 0.01, std::numeric_limits<Real>::infinity()};
    Tally tally;
    int flush = 0;
    for (int n = 0; n < 3000; ++n) {
        const Vec3 where(10.0 * unit(random), 10.0 * unit(random), 10.0 * unit(random));
        const Quat orientation = n % 3 == 0 ? Quat(1, 0, 0, 0) : randomOrientation(random);
        const Vec3 extents = n % 2 == 0 ? Vec3(std::abs(randomExtents(random).x))
                                        : randomExtents(random);
        const CuboidFrame reference = cuboidFrame({where, orientation}, extents);
        CuboidFrame incident = n % 3 == 1 ? alignedWith(reference, 0, extents)
                                          : cuboidFrame({Vec3(0.0), orientation *
                                                         tilt(random, 1e-10)}, extents);
        const int referenceFace = faceChoice(random);
        const int axis = faceAxis(referenceFace);
        const Real size = boxSize(reference, incident);
        const int shift1 = shiftChoice(random);
        const int shift2 = n % 4 == 0 ? 0 : shiftChoice(random);
        // Shifts in quarter sides: 0 flush, 2 half a side, 4 a whole side (edge on edge).
        const Vec3 aside(0.5 * shift1 * extents[(axis + 1) % 3] + 1e-12 * size * unit(random),
                         0.5 * shift2 * extents[(axis + 2) % 3] + 1e-12 * size * unit(random),
                         0.0);
        // Touching only where the margin is not 0: a separation within rounding of the margin
        // may be kept or not.
        const Real gap = n % 5 == 0 && n % 3 != 0 ? 0.0 : 1e-3 * unit(random);
        placeOnFace(reference, referenceFace, incident, aside, gap);
        expectSameClipping(reference, referenceFace, incident, margins[n % 3], tally);
        if (::testing::Test::HasFatalFailure()) {
            return;
        }
        if (shift1 == 0 && shift2 == 0 && (gap < -1e-6 || n % 3 != 0)) {
            // Flush: the incident face's 4 corners, each on its two edges and no side plane.
            const ClippedPoints points =
                clipIncidentFace(reference, referenceFace, incident, false, margins[n % 3]);
            ASSERT_EQ(points.count, 4);
            for (int m = 0; m < 4; ++m) {
                EXPECT_EQ(points.points[m].id & 0xFFu, (1u << m) | (1u << ((m + 3) % 4)));
            }
            ++flush;
        }
    }
    EXPECT_GT(flush, 20);
    EXPECT_EQ(tally.notClearCut, 0);
    for (const int count : {0, 2, 4}) {
        EXPECT_GT(tally.byCount[count], 0) << count << " points";
    }
}

/// Two equal cubes of half side `half`, axes along the world's, B on A's +y face with its
/// bottom face exactly on it and shifted `shift` along x.
std::pair<CuboidFrame, CuboidFrame> cubeOnCube(Real half, Real shift)
{
    const CuboidFrame a{Vec3(0.0), {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}, Vec3(half)};
    CuboidFrame b = a;
    b.centre = Vec3(shift, 2.0 * half, 0.0);
    return {a, b};
}

TEST(CuboidFaceClipping, CornersWithinTheOnPlaneShareOfTheHalfWidthStay)
{
    // (9.7): within kOnSidePlane = 1e-9 of the half-width a corner lies on the side plane and
    // stays a corner (edges only, no side plane); beyond it the face is cut.
    constexpr int kPlusY = 2;
    const auto [a, b] = cubeOnCube(1.5, 1.2e-9);  // 1.2e-9 < 1.5e-9: on the plane
    const ClippedPoints kept = clipIncidentFace(a, kPlusY, b, false, 0.0);
    ASSERT_EQ(kept.count, 4);
    for (int m = 0; m < 4; ++m) {
        EXPECT_EQ(kept.points[m].id & 0xFFu, (1u << m) | (1u << ((m + 3) % 4))) << m;
        EXPECT_EQ(kept.points[m].separation, 0.0) << m;
    }
    const auto [c, d] = cubeOnCube(0.05, 1.2e-10);  // 1.2e-10 > 5e-11: outside, cut
    const ClippedPoints cut = clipIncidentFace(c, kPlusY, d, false, 0.0);
    ASSERT_EQ(cut.count, 4);
    int onSidePlane = 0;
    for (int m = 0; m < 4; ++m) {
        onSidePlane += (cut.points[m].id & 0xF0u) != 0;
    }
    EXPECT_EQ(onSidePlane, 2);
}

TEST(CuboidFaceClipping, TouchingPointsAreKeptAtZeroMargin)
{
    // A separation equal to the margin is within it (9.7): s <= mu.
    const auto [a, b] = cubeOnCube(1.0, 0.5);
    const ClippedPoints points = clipIncidentFace(a, 2, b, true, 0.0);
    ASSERT_EQ(points.count, 4);
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(points.points[i].separation, 0.0);
        EXPECT_EQ(points.points[i].position.y, 1.0);
    }
}

} // namespace
} // namespace tumble
