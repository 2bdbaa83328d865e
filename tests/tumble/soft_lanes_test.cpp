// The soft step's four-lane passes give the bits of the one-manifold passes over the same
// manifolds one after the other (docs/physics/12-soft-step.md, (12.9)).
#include "dynamics/constraint_colouring.hpp"
#include "dynamics/soft_contact_solver.hpp"
#include "dynamics/soft_lanes.hpp"
#include "support/random_bodies.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <random>
#include <vector>

namespace tumble {
namespace {

/// A random soft island in colour order: dynamic bodies of assorted masses and inertias, moved
/// and turned a little since the step began, the static body after them, and manifolds of one to
/// four points between random pairs (a fifth with the static body), their gaps both open
/// (speculative) and closed, each started with impulses as a warm start leaves them.
struct RandomSoftIsland {
    std::vector<SoftBody> bodies;
    std::vector<SoftManifold> manifolds;
    SoftColours colours;

    /// Manifolds of `fewestPoints` to four points.
    RandomSoftIsland(std::uint32_t seed, std::uint32_t bodyCount, int count, int fewestPoints = 1)
    {
        std::mt19937_64 random(seed);
        const auto unit = [&] { return testing::randomUnit(random); };
        const auto vector = [&] { return testing::randomVector(random); };
        for (std::uint32_t i = 0; i < bodyCount; ++i) {
            SoftBody& body = bodies.emplace_back();
            body.linearVelocity = vector();
            body.angularVelocity = vector();
            body.deltaPosition = 1e-3 * vector();
            body.deltaRotation = glm::mat3_cast(glm::normalize(Quat(1.0, 1e-3 * vector())));
            body.invMass = testing::randomInverseMass(random);
            body.invInertia = testing::randomInverseInertia(random);
        }
        bodies.emplace_back(); // the static geometry
        std::uniform_int_distribution<std::uint32_t> pick(0, bodyCount - 1);
        std::vector<SoftManifold> drawn;
        for (int n = 0; n < count; ++n) {
            SoftManifold& m = drawn.emplace_back();
            m.bodyB = pick(random);
            m.bodyA = random() % 5 == 0 ? bodyCount : pick(random);
            if (m.bodyA == m.bodyB) {
                m.bodyA = bodyCount;
            }
            m.againstStatic = m.bodyA == bodyCount;
            m.normal = glm::normalize(vector() + Vec3(0.0, 0.1, 0.0));
            orthonormalBasis(m.normal, m.tangent1, m.tangent2);
            m.friction = random() % 4 == 0 ? 0.0 : 0.05 + 0.5 * (0.5 + 0.5 * unit());
            m.pointCount =
                fewestPoints + static_cast<int>(random() % static_cast<unsigned>(5 - fewestPoints));
            for (int k = 0; k < m.pointCount; ++k) {
                SoftPoint& p = m.points[k];
                p.anchorA = m.againstStatic ? Vec3(0.0) : vector();
                p.anchorB = vector();
                p.baseSeparation = 0.02 * unit();
                p.normalImpulse = 0.5 + 0.5 * unit();
                p.relativeVelocity = unit();
            }
            m.restitution = random() % 2 == 0 ? 0.0 : 0.5;
            prepareSoftRows(m, bodies);
            m.frictionImpulse1 = 0.1 * unit();
            m.frictionImpulse2 = 0.1 * unit();
            m.twistImpulse = 0.05 * unit();
        }
        std::vector<ProxyPair> ends;
        for (const SoftManifold& m : drawn) {
            ends.push_back({m.bodyA, m.bodyB});
        }
        std::vector<std::uint8_t> isStatic(bodyCount + 1, 0);
        isStatic.back() = 1;
        const ConstraintColours colouring =
            colourConstraints(ends, isStatic, kMaxConstraintColours);
        for (const std::uint32_t index : colouring.constraints) {
            manifolds.push_back(drawn[index]);
        }
        colours.offsets = colouring.offsets;
    }
};

/// Two sub-steps of passes as the soft step makes them (warm start, biased pass, relax pass),
/// then restitution; what the step leaves of each manifold.
std::vector<SoftContactResult> runPasses(RandomSoftIsland& island, int threads,
                                         SoftLanes* lanes)
{
    const Real h = 1.0 / 240.0;
    const SoftSolveSettings settings{makeSoftness(30.0, 10.0, h), makeSoftness(60.0, 5.0, h),
                                     1.0 / h, 3.0};
    // with lanes the passes are given the overflow group's manifolds only
    const std::size_t overflow = island.colours.offsets[island.colours.offsets.size() - 2];
    const std::size_t unpacked = lanes != nullptr ? overflow : 0;
    const std::span<SoftManifold> swept = std::span(island.manifolds).subspan(unpacked);
    if (lanes != nullptr) {
        lanes->pack(island.manifolds, island.colours, island.bodies, threads);
    }
    for (int substep = 0; substep < 2; ++substep) {
        warmStartSoft(swept, island.bodies, island.colours, threads, lanes);
        solveSoft(swept, island.bodies, settings, true, island.colours, threads, lanes);
        solveSoft(swept, island.bodies, settings, false, island.colours, threads, lanes);
    }
    restituteSoft(swept, island.bodies, 0.1, island.colours, threads, lanes);
    std::vector<SoftContactResult> results(island.manifolds.size());
    for (std::size_t m = unpacked; m < results.size(); ++m) {
        results[m] = softResultOf(island.manifolds[m]);
    }
    if (lanes != nullptr) {
        lanes->results(results, threads);
        lanes->unpack(island.manifolds, threads);
    }
    return results;
}

void expectSameBits(const Vec3& a, const Vec3& b)
{
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(std::bit_cast<std::uint64_t>(a[i]), std::bit_cast<std::uint64_t>(b[i]));
    }
}

void expectSameBits(Real a, Real b)
{
    EXPECT_EQ(std::bit_cast<std::uint64_t>(a), std::bit_cast<std::uint64_t>(b));
}

void expectSameResults(const std::vector<SoftContactResult>& one,
                       const std::vector<SoftContactResult>& other)
{
    ASSERT_EQ(one.size(), other.size());
    for (std::size_t m = 0; m < one.size(); ++m) {
        ASSERT_EQ(one[m].pointCount, other[m].pointCount);
        for (int k = 0; k < one[m].pointCount; ++k) {
            expectSameBits(one[m].normalImpulses[k], other[m].normalImpulses[k]);
            expectSameBits(one[m].normalWork[k], other[m].normalWork[k]);
        }
        expectSameBits(one[m].frictionImpulse, other[m].frictionImpulse);
        expectSameBits(one[m].twistImpulse, other[m].twistImpulse);
        expectSameBits(one[m].frictionWork, other[m].frictionWork);
    }
}

void expectSameIslands(const RandomSoftIsland& one, const RandomSoftIsland& other)
{
    ASSERT_EQ(one.manifolds.size(), other.manifolds.size());
    for (std::size_t i = 0; i < one.bodies.size(); ++i) {
        expectSameBits(one.bodies[i].linearVelocity, other.bodies[i].linearVelocity);
        expectSameBits(one.bodies[i].angularVelocity, other.bodies[i].angularVelocity);
    }
    for (std::size_t m = 0; m < one.manifolds.size(); ++m) {
        const SoftManifold& a = one.manifolds[m];
        const SoftManifold& b = other.manifolds[m];
        for (int k = 0; k < a.pointCount; ++k) {
            expectSameBits(a.points[k].normalImpulse, b.points[k].normalImpulse);
            expectSameBits(a.points[k].maxNormalImpulse, b.points[k].maxNormalImpulse);
            expectSameBits(a.points[k].normalWork, b.points[k].normalWork);
        }
        expectSameBits(a.frictionImpulse1, b.frictionImpulse1);
        expectSameBits(a.frictionImpulse2, b.frictionImpulse2);
        expectSameBits(a.twistImpulse, b.twistImpulse);
        expectSameBits(a.frictionWork, b.frictionWork);
    }
}

/// Runs the passes on a copy of `island` one manifold at a time and on another copy in `lanes`
/// over `threads`, and expects the same bits of both.
void expectLanesGiveTheBitsOfOneAtATime(const RandomSoftIsland& island, int threads,
                                        SoftLanes& lanes)
{
    RandomSoftIsland scalar = island;
    RandomSoftIsland wide = island;
    const std::vector<SoftContactResult> one = runPasses(scalar, 1, nullptr);
    expectSameResults(one, runPasses(wide, threads, &lanes));
    expectSameIslands(scalar, wide);
}

TEST(SoftLanes, GiveTheBitsOfOneManifoldAtATime)
{
    RandomSoftIsland scalar(11, 60, 300);
    RandomSoftIsland wide = scalar;
    ASSERT_GT(scalar.colours.offsets.size(), 3u);
    const std::vector<SoftContactResult> one = runPasses(scalar, 1, nullptr);
    SoftLanes lanes;
    expectSameResults(one, runPasses(wide, 1, &lanes));
    expectSameIslands(scalar, wide);
    // the passes did work: some impulse reached zero; and restitution had points to act on
    // (bouncing manifolds' points that pushed and approached faster than the threshold)
    int released = 0;
    int bouncing = 0;
    for (std::size_t m = 0; m < scalar.manifolds.size(); ++m) {
        const SoftManifold& after = scalar.manifolds[m];
        for (int k = 0; k < after.pointCount; ++k) {
            released += after.points[k].normalImpulse == 0.0 ? 1 : 0;
            bouncing += after.restitution > 0.0 && after.points[k].maxNormalImpulse > 0.0 &&
                               after.points[k].relativeVelocity < -0.1
                           ? 1
                           : 0;
        }
    }
    EXPECT_GT(released, 0);
    EXPECT_GT(bouncing, 0);
}

TEST(SoftLanes, BlocksOfFourPointManifoldsGiveTheSameBits)
{
    // every manifold of four points (faces on faces): every full block takes the pass without
    // the points' masks (LaneBlock::everyPoint), each colour's last block the pass with them
    SoftLanes lanes;
    expectLanesGiveTheBitsOfOneAtATime(RandomSoftIsland(14, 60, 300, 4), 1, lanes);
}

TEST(SoftLanes, LanesPackedAgainOverAnotherIslandGiveTheSameBits)
{
    // the blocks are filled where the last island left them: an island of four-point manifolds
    // first (every field of every lane written), then one of one to four points, whose lanes
    // and points not present must read as empty, not as what the first island left
    RandomSoftIsland first(15, 60, 300, 4);
    SoftLanes lanes;
    runPasses(first, 1, &lanes);
    expectLanesGiveTheBitsOfOneAtATime(RandomSoftIsland(16, 60, 300), 1, lanes);
}

TEST(SoftLanes, LargeColoursOnTwoThreadsGiveTheSameBits)
{
    // 700 bodies and 1500 manifolds: the first colours hold 256 manifolds or more, so their
    // blocks are shared out over the threads
    const RandomSoftIsland island(12, 700, 1500);
    ASSERT_GE(island.colours.offsets[1] - island.colours.offsets[0], kThreadedColourManifolds);
    SoftLanes lanes;
    expectLanesGiveTheBitsOfOneAtATime(island, 2, lanes);
}

TEST(SoftLanes, EachBlocksWorkIsItsManifoldsWorkInOrderAndThePushedAreMarked)
{
    // SoftLanes::work: a block's normal work adds its lanes' points in order, its friction work
    // its lanes' in order, bit for bit as from the manifolds' results; a manifold pushed if one
    // of its points' impulses is positive
    RandomSoftIsland island(17, 700, 1500);
    SoftLanes lanes;
    const std::vector<SoftContactResult> results = runPasses(island, 2, &lanes);
    std::vector<SoftBlockWork> blockWork;
    std::vector<std::uint8_t> pushed(results.size(), 2);
    lanes.work(blockWork, pushed, 2);
    const std::vector<std::uint32_t>& offsets = island.colours.offsets;
    const std::size_t lanesOfABlock = SoftLanes::manifoldsPerBlock();
    std::size_t block = 0;
    int pushing = 0;
    int idle = 0;
    // every group but the last (the overflow) is a colour of blocks of lanesOfABlock manifolds
    for (std::size_t c = 0; c + 2 < offsets.size(); ++c) {
        for (std::size_t first = offsets[c]; first < offsets[c + 1]; first += lanesOfABlock, ++block) {
            SoftBlockWork expected;
            for (std::size_t m = first; m < std::min<std::size_t>(first + lanesOfABlock, offsets[c + 1]);
                 ++m) {
                bool pushes = false;
                for (int k = 0; k < results[m].pointCount; ++k) {
                    expected.normal += results[m].normalWork[k];
                    pushes = pushes || results[m].normalImpulses[k] > 0.0;
                }
                expected.friction += results[m].frictionWork;
                EXPECT_EQ(pushed[m], pushes ? 1 : 0);
                (pushes ? pushing : idle) += 1;
            }
            ASSERT_LT(block, blockWork.size());
            expectSameBits(blockWork[block].normal, expected.normal);
            expectSameBits(blockWork[block].friction, expected.friction);
        }
    }
    EXPECT_EQ(block, blockWork.size());
    EXPECT_GT(pushing, 0);
    EXPECT_GT(idle, 0);
}

TEST(SoftLanes, AnOverflowGroupAfterTheLanesGivesTheSameBits)
{
    // 8 bodies and 500 manifolds need more colours than kMaxConstraintColours: the rest is the
    // overflow group, swept one manifold at a time after the lanes, from its own array
    const RandomSoftIsland island(13, 8, 500);
    const std::vector<std::uint32_t>& offsets = island.colours.offsets;
    ASSERT_GT(offsets.back() - offsets[offsets.size() - 2], 10u);
    SoftLanes lanes;
    expectLanesGiveTheBitsOfOneAtATime(island, 2, lanes);
}

} // namespace
} // namespace tumble
