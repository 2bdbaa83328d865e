// The cuboid axis search against the direct form of (9.1)-(9.3) (tests/support/
// direct_axis_search.hpp): the rotation-matrix form (9.2a)-(9.2c) must choose the same axis,
// with the same separation and normal to rounding, and leave early on the same axis
// (docs/physics/09-box-box.md).
#include "collision/cuboid_separating_axis.hpp"

#include "support/direct_axis_search.hpp"
#include "support/glm_printers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>

namespace tumble {
namespace {

using testing::DirectAxis;
using testing::directAxis;
using testing::DirectAxisSearch;
using testing::normalTolerance;
using testing::separationTolerance;

Real boxSize(const CuboidFrame& a, const CuboidFrame& b)
{
    return std::max({a.halfExtents.x, a.halfExtents.y, a.halfExtents.z, b.halfExtents.x,
                     b.halfExtents.y, b.halfExtents.z});
}

/// What one comparison found, for the tallies that show the cases reach every branch.
enum class Outcome { FaceA, FaceB, EdgePair, Separated, NotClearCut };

/// The search agrees with the direct form: on every decision when the reference's were clear-
/// cut, or when `exact` (each a_i . b_j is 0 or +-1, so both forms compute the same separations
/// bit for bit and must break exact ties alike); else on the value of the axis it chose.
Outcome expectSameSearch(const CuboidFrame& a, const CuboidFrame& b, Real margin, bool exact)
{
    const Real size = boxSize(a, b);
    DirectAxisSearch reference{a, b, margin, size};
    const AxisSearch expected = reference.search();
    const AxisSearch actual = searchContactAxis(a, b, margin);
    EXPECT_GE(actual.largestSeparation, reference.largestLow);
    EXPECT_LE(actual.largestSeparation, reference.largestHigh);
    if (reference.clearCut || exact) {
        EXPECT_EQ(actual.axis.has_value(), expected.axis.has_value());
        if (!actual.axis || !expected.axis) {
            return Outcome::Separated;
        }
        EXPECT_EQ(actual.axis->kind, expected.axis->kind);
        EXPECT_EQ(actual.axis->axisA, expected.axis->axisA);
        EXPECT_EQ(actual.axis->axisB, expected.axis->axisB);
        const DirectAxis direct = directAxis(a, b, *expected.axis);
        EXPECT_NEAR(actual.axis->separation, expected.axis->separation,
                    separationTolerance(direct, size));
        EXPECT_TRUE(
            testing::near(actual.axis->normal, expected.axis->normal, normalTolerance(direct)));
        return static_cast<Outcome>(expected.axis->kind);
    }
    // A decision within rounding may go either way (one of them may leave early on an axis
    // within rounding of the margin; largestSeparation is held to its bounds above).
    if (actual.axis) {
        const DirectAxis direct = directAxis(a, b, *actual.axis);
        EXPECT_NEAR(actual.axis->separation, direct.axis.separation,
                    separationTolerance(direct, size));
        EXPECT_NEAR(std::abs(glm::dot(actual.axis->normal, direct.axis.normal)), 1.0,
                    normalTolerance(direct));
    }
    return Outcome::NotClearCut;
}

struct Tally {
    std::array<int, 5> count{};
    void add(Outcome outcome) { ++count[static_cast<int>(outcome)]; }
    int operator[](Outcome outcome) const { return count[static_cast<int>(outcome)]; }
};

Quat randomOrientation(std::mt19937& random)
{
    std::normal_distribution<Real> gaussian;
    const Real w = gaussian(random);
    const Real x = gaussian(random);
    const Real y = gaussian(random);
    const Real z = gaussian(random);
    return glm::normalize(Quat(w, x, y, z));
}

Vec3 randomExtents(std::mt19937& random)
{
    std::uniform_real_distribution<Real> logExtent(std::log(0.05), std::log(2.0));
    const Real x = std::exp(logExtent(random));
    const Real y = std::exp(logExtent(random));
    const Real z = std::exp(logExtent(random));
    return Vec3(x, y, z);
}

/// A turn of 10^-9 to 10^-1.5 rad about a random axis.
Quat smallTurn(std::mt19937& random)
{
    std::uniform_real_distribution<Real> logAngle(-9.0, -1.5);
    const Real angle = std::pow(10.0, logAngle(random));
    return glm::angleAxis(angle, glm::normalize(Vec3(randomOrientation(random) * Vec3(1, 0, 0))));
}

/// The 24 right-handed frames of signed unit axes: B's axes along A's in any order and sense.
std::array<std::array<Vec3, 3>, 24> signedPermutationFrames()
{
    constexpr std::array<std::array<int, 3>, 6> kOrders{
        {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};
    std::array<std::array<Vec3, 3>, 24> frames{};
    int n = 0;
    for (int order = 0; order < 6; ++order) {
        const Real parity = order < 3 ? 1.0 : -1.0;
        for (int signs = 0; signs < 4; ++signs) {
            const Real s0 = (signs & 1) != 0 ? -1.0 : 1.0;
            const Real s1 = (signs & 2) != 0 ? -1.0 : 1.0;
            const std::array<Real, 3> sign{s0, s1, parity * s0 * s1};  // determinant +1
            for (int k = 0; k < 3; ++k) {
                frames[n][k] = Vec3(0.0);
                frames[n][k][kOrders[order][k]] = sign[k];
            }
            ++n;
        }
    }
    return frames;
}

TEST(CuboidSeparatingAxis, RandomPairsGetTheAxisOfTheDirectForm)
{
    // Random sizes and orientations, centres from deep overlap to well apart.
    std::mt19937 random(20260);
    std::uniform_real_distribution<Real> reach(0.0, 1.3);
    std::uniform_int_distribution<int> marginChoice(0, 2);
    const std::array<Real, 3> margins{0.0, 5e-3, 0.1};
    Tally tally;
    for (int n = 0; n < 4000; ++n) {
        const Vec3 extentsA = randomExtents(random);
        const Vec3 extentsB = randomExtents(random);
        const Vec3 centreA = 3.0 * Vec3(randomOrientation(random) * Vec3(0.5, 0.0, 0.0));
        const Vec3 direction = Vec3(randomOrientation(random) * Vec3(1.0, 0.0, 0.0));
        const Vec3 centreB =
            centreA + reach(random) * (glm::length(extentsA) + glm::length(extentsB)) * direction;
        const CuboidFrame a = cuboidFrame({centreA, randomOrientation(random)}, extentsA);
        const CuboidFrame b = cuboidFrame({centreB, randomOrientation(random)}, extentsB);
        tally.add(expectSameSearch(a, b, margins[marginChoice(random)], false));
    }
    EXPECT_GT(tally[Outcome::Separated], 400);
    EXPECT_GT(tally[Outcome::FaceA], 400);
    EXPECT_GT(tally[Outcome::FaceB], 400);
    EXPECT_GT(tally[Outcome::EdgePair], 200);
    EXPECT_LT(tally[Outcome::NotClearCut], 40);
}

TEST(CuboidSeparatingAxis, NearlyParallelBoxesGetTheAxisOfTheDirectForm)
{
    // B turned from A, or from A with its axes swapped by a quarter turn, by 1e-9 to 0.03 rad,
    // face to face within +-0.05 of the box size: edge pairs from parallel through the skip
    // threshold (9.3) to well apart, and faces of nearly equal separation.
    std::mt19937 random(9309);
    std::uniform_real_distribution<Real> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> axisChoice(0, 2);
    const Quat quarter = glm::angleAxis(0.5 * std::numbers::pi, glm::normalize(Vec3(1, 1, 0)));
    const Quat none(1.0, 0.0, 0.0, 0.0);
    Tally tally;
    for (int n = 0; n < 3000; ++n) {
        const Vec3 extentsA = randomExtents(random);
        const Vec3 extentsB = n % 4 == 0 ? extentsA : randomExtents(random);
        const Quat orientationA = randomOrientation(random);
        const Quat orientationB =
            glm::normalize(orientationA * smallTurn(random) * (n % 3 == 0 ? quarter : none));
        const CuboidFrame a = cuboidFrame({Vec3(0.7, -0.2, 1.1), orientationA}, extentsA);
        CuboidFrame b = cuboidFrame({Vec3(0.0), orientationB}, extentsB);
        const int k = axisChoice(random);
        const Real reachB = projectedRadius(b, a.axes[k]);
        Vec3 offset = (extentsA[k] + reachB + 0.05 * boxSize(a, b) * unit(random)) * a.axes[k];
        for (int l = 1; l < 3; ++l) {
            const int m = (k + l) % 3;
            offset += 0.9 * unit(random) * (extentsA[m] + projectedRadius(b, a.axes[m])) *
                      a.axes[m];
        }
        b.centre = a.centre + (n % 2 == 0 ? offset : -offset);
        tally.add(expectSameSearch(a, b, 5e-3, false));
    }
    EXPECT_GT(tally[Outcome::Separated], 300);
    EXPECT_GT(tally[Outcome::FaceA] + tally[Outcome::FaceB], 1000);
    EXPECT_LT(tally[Outcome::NotClearCut], 30);
}

TEST(CuboidSeparatingAxis, NearlyParallelEdgesAcrossADiagonalGetTheAxisOfTheDirectForm)
{
    // Two nearly parallel beams edge to edge, apart by g and 1.3 g along the other two axes:
    // a_k and b_k turned 10^-6.5 to 10^-2 rad about the diagonal w across them, so L_kk = +-w
    // with the angle for its sine, and the gap along w about 1.63 g. Margins of 1.45 g and 2 g
    // make that edge axis the one left on or the one chosen; below the sine of (9.3) the faces
    // decide.
    std::mt19937 random(4401);
    std::uniform_real_distribution<Real> logAngle(-6.5, -2.0);
    std::uniform_real_distribution<Real> unit(-1.0, 1.0);
    Tally tally;
    for (int n = 0; n < 2000; ++n) {
        const int k = n % 3;
        const int k1 = (k + 1) % 3;
        const int k2 = (k + 2) % 3;
        const Vec3 extentsA = randomExtents(random);
        const Vec3 extentsB = randomExtents(random);
        const Real gap = 0.02 * std::abs(unit(random)) * std::max(extentsA[k1], extentsA[k2]);
        Vec3 across(0.0);
        across[k1] = 1.0;
        across[k2] = 1.0;
        const Quat orientationA = randomOrientation(random);
        const Real angle = std::pow(10.0, logAngle(random));
        const Quat orientationB =
            glm::normalize(orientationA * glm::angleAxis(angle, glm::normalize(across)));
        const CuboidFrame a = cuboidFrame({Vec3(-0.4, 0.9, 0.2), orientationA}, extentsA);
        CuboidFrame b = cuboidFrame({Vec3(0.0), orientationB}, extentsB);
        Vec3 offset = unit(random) * extentsA[k] * a.axes[k];
        offset += (extentsA[k1] + extentsB[k1] + gap) * a.axes[k1];
        offset += (extentsA[k2] + extentsB[k2] + 1.3 * gap) * a.axes[k2];
        b.centre = a.centre + offset;
        tally.add(expectSameSearch(a, b, (n % 2 == 0 ? 1.45 : 2.0) * gap, false));
    }
    EXPECT_GT(tally[Outcome::Separated], 500);
    EXPECT_GT(tally[Outcome::EdgePair], 500);
    EXPECT_LT(tally[Outcome::NotClearCut], 20);
}

TEST(CuboidSeparatingAxis, AxisAlignedTouchingBoxesGetTheAxisOfTheDirectFormExactly)
{
    // B's axes along A's in each of the 24 ways, side by side, stacked face to face and corner
    // to corner, touching, slightly apart or in. Every product a_i . b_j is 0 or +-1 exactly,
    // so both forms compute the same separations bit for bit and must break the exact ties
    // among faces and edge pairs the same way.
    std::mt19937 random(1996);
    std::uniform_real_distribution<Real> unit(-1.0, 1.0);
    const std::array<Real, 5> gaps{0.0, 1e-3, -1e-3, 0.02, -0.3};
    Tally tally;
    for (const std::array<Vec3, 3>& axesB : signedPermutationFrames()) {
        for (int n = 0; n < 12; ++n) {
            const Vec3 extentsA = n % 3 == 0 ? Vec3(1.0) : randomExtents(random);
            const CuboidFrame a{Vec3(0.3, -1.7, 2.1), {Vec3(1, 0, 0), Vec3(0, 1, 0),
                                                       Vec3(0, 0, 1)}, extentsA};
            CuboidFrame b{Vec3(0.0), axesB, n % 3 == 0 ? Vec3(1.0) : randomExtents(random)};
            const Real gap = gaps[n % gaps.size()];
            const int k = n % 3;
            Vec3 offset(0.0);
            for (int m = 0; m < 3; ++m) {
                const Real touching = extentsA[m] + projectedRadius(b, a.axes[m]) + gap;
                const bool corner = n % 4 == 3;
                const Real lateral = n % 2 == 0 ? 0.0 : 0.9 * unit(random) * touching;
                offset[m] = m == k || corner ? touching : lateral;
            }
            for (const Real sign : {1.0, -1.0}) {
                b.centre = a.centre + sign * offset;
                tally.add(expectSameSearch(a, b, 5e-3, true));
                tally.add(expectSameSearch(b, a, 5e-3, true));
            }
        }
    }
    // B's faces and the edge pairs only tie with A's faces here, and ties go to A (9.5).
    EXPECT_GT(tally[Outcome::Separated], 100);
    EXPECT_GT(tally[Outcome::FaceA], 100);
}

} // namespace
} // namespace tumble
