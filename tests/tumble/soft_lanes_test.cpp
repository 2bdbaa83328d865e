// The soft step's four-lane passes give the bits of the one-manifold passes over the same
// manifolds one after the other (docs/physics/12-soft-step.md, (12.9)).
#include "dynamics/constraint_colouring.hpp"
#include "dynamics/soft_contact_solver.hpp"
#include "dynamics/soft_lanes.hpp"
#include "support/random_bodies.hpp"

#include <gtest/gtest.h>

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

    RandomSoftIsland(std::uint32_t seed, std::uint32_t bodyCount, int count)
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
            m.pointCount = 1 + static_cast<int>(random() % 4);
            for (int k = 0; k < m.pointCount; ++k) {
                SoftPoint& p = m.points[k];
                p.anchorA = m.againstStatic ? Vec3(0.0) : vector();
                p.anchorB = vector();
                p.baseSeparation = 0.02 * unit();
                p.normalImpulse = 0.5 + 0.5 * unit();
            }
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

/// Two sub-steps of passes as the soft step makes them: warm start, biased pass, relax pass.
void runPasses(RandomSoftIsland& island, int threads, SoftLanes* lanes)
{
    const Real h = 1.0 / 240.0;
    const SoftSolveSettings settings{makeSoftness(30.0, 10.0, h), makeSoftness(60.0, 5.0, h),
                                     1.0 / h, 3.0};
    if (lanes != nullptr) {
        lanes->pack(island.manifolds, island.colours, island.bodies, threads);
    }
    for (int substep = 0; substep < 2; ++substep) {
        warmStartSoft(island.manifolds, island.bodies, island.colours, threads, lanes);
        solveSoft(island.manifolds, island.bodies, settings, true, island.colours, threads, lanes);
        solveSoft(island.manifolds, island.bodies, settings, false, island.colours, threads,
                  lanes);
    }
    if (lanes != nullptr) {
        lanes->unpack(island.manifolds, threads);
    }
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

TEST(SoftLanes, GiveTheBitsOfOneManifoldAtATime)
{
    RandomSoftIsland scalar(11, 60, 300);
    RandomSoftIsland wide = scalar;
    ASSERT_GT(scalar.colours.offsets.size(), 3u);
    runPasses(scalar, 1, nullptr);
    SoftLanes lanes;
    runPasses(wide, 1, &lanes);
    expectSameIslands(scalar, wide);
    // the passes did work: some impulse reached zero, some disc its edge
    int released = 0;
    for (const SoftManifold& m : scalar.manifolds) {
        for (int k = 0; k < m.pointCount; ++k) {
            released += m.points[k].normalImpulse == 0.0 ? 1 : 0;
        }
    }
    EXPECT_GT(released, 0);
}

TEST(SoftLanes, LargeColoursOnTwoThreadsGiveTheSameBits)
{
    // 700 bodies and 1500 manifolds: the first colours hold 256 manifolds or more, so their
    // blocks are shared out over the threads
    RandomSoftIsland scalar(12, 700, 1500);
    ASSERT_GE(scalar.colours.offsets[1] - scalar.colours.offsets[0], kThreadedColourManifolds);
    RandomSoftIsland wide = scalar;
    runPasses(scalar, 1, nullptr);
    SoftLanes lanes;
    runPasses(wide, 2, &lanes);
    expectSameIslands(scalar, wide);
}

} // namespace
} // namespace tumble
