// The four-lane sweep of a large island's colours gives the bits of the one-point step over the
// same runs one after the other (docs/physics/11-island-solver.md, (11.5d)).
#include "dynamics/island_solver.hpp"
#include "dynamics/wide_sweep.hpp"
#include "support/random_bodies.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <vector>

namespace tumble {
namespace {

/// A random island: `bodyCount` dynamic bodies of assorted masses and inertias, the static body
/// after them, and manifolds of one to four points between random pairs (a fifth of them with
/// the static body), each prepared with a sub-step target and given a starting impulse. With
/// small friction coefficients many friction steps land on the cone's edge (Newton's method),
/// and with zero friction on points that slide, on a negligible bound.
struct RandomIsland {
    std::vector<SolverBody> bodies;
    std::vector<ContactConstraint> constraints;

    RandomIsland(std::uint32_t seed, std::uint32_t bodyCount, int manifolds)
    {
        std::mt19937_64 random(seed);
        const auto unit = [&] { return testing::randomUnit(random); };
        const auto vector = [&] { return testing::randomVector(random); };
        for (std::uint32_t i = 0; i < bodyCount; ++i) {
            SolverBody& body = bodies.emplace_back();
            body.linearVelocity = vector();
            body.angularVelocity = vector();
            body.invMass = testing::randomInverseMass(random);
            body.invInertiaWorld = testing::randomInverseInertia(random);
        }
        bodies.emplace_back(); // the static geometry
        const auto staticBody = bodyCount;
        std::uniform_int_distribution<std::uint32_t> pick(0, bodyCount - 1);
        std::uniform_int_distribution<int> pointCount(1, 4);
        for (int m = 0; m < manifolds; ++m) {
            const std::uint32_t b = pick(random);
            std::uint32_t a = random() % 5 == 0 ? staticBody : pick(random);
            if (a == b) {
                a = staticBody;
            }
            const Vec3 normal = glm::normalize(vector() + Vec3(0.0, 0.1, 0.0));
            const Real friction = random() % 4 == 0 ? 0.0 : 0.05 + 0.3 * (0.5 + 0.5 * unit());
            const int points = pointCount(random);
            for (int k = 0; k < points; ++k) {
                ContactConstraint& c = constraints.emplace_back();
                c.bodyA = a;
                c.bodyB = b;
                c.normal = normal;
                c.offsetA = vector();
                c.offsetB = vector();
                c.separation = random() % 3 == 0 ? 0.01 * (0.5 + 0.5 * unit()) : 0.0;
                c.kineticFriction = friction;
                c.staticFriction = friction;
                prepareConstraint(c, bodies, {ConstraintTarget::Substep, 1.0 / 60, 1e-4, 0.05});
                c.normalImpulse = 0.5 + 0.5 * unit();
                c.tangentImpulse1 = 0.1 * unit();
                c.tangentImpulse2 = 0.1 * unit();
            }
        }
    }
};

bool sameBits(Real a, Real b)
{
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

TEST(LaneSweep, GivesTheBitsOfTheOnePointStepRunAfterRun)
{
    for (const std::uint32_t seed : {1u, 2u, 3u}) {
        const RandomIsland island(seed, 300, 900);
        SweepSchedule schedule;
        scheduleSweeps(island.constraints, island.bodies, schedule);
        ASSERT_TRUE(schedule.coloured) << "enough points to sweep colour by colour";
        ASSERT_GT(schedule.colours.colourCount, 4u);

        // the reference: each colour's runs one after the other, each run one sweep of the
        // one-point step (a solve of so few points keeps their order)
        std::vector<SolverBody> oneByOne = island.bodies;
        std::vector<ContactConstraint> reference = island.constraints;
        std::vector<SolverBody> fourByFour = island.bodies;
        std::vector<ContactConstraint> packed = island.constraints;
        LaneSweeps lanes;
        lanes.pack(schedule, packed);
        std::size_t edgeSteps = 0;
        for (int sweep = 0; sweep < 3; ++sweep) {
            for (std::uint32_t colour = 0; colour < schedule.colours.colourCount; ++colour) {
                for (const std::uint32_t run : schedule.colours.colour(colour)) {
                    const std::uint32_t first = schedule.runStart[run];
                    const std::uint32_t count = schedule.runStart[run + 1] - first;
                    solveConstraints(std::span(reference).subspan(first, count), oneByOne, 1,
                                     0.0);
                }
                SweepMaxima maxima;
                const auto [firstBlock, lastBlock] = lanes.blocksOf(colour);
                lanes.sweep(firstBlock, lastBlock, fourByFour, maxima);
            }
        }
        lanes.unpack(packed);
        for (std::size_t i = 0; i < reference.size(); ++i) {
            const ContactConstraint& want = reference[i];
            const ContactConstraint& got = packed[i];
            edgeSteps += want.frictionShift > 0.0 ? 1 : 0;
            EXPECT_TRUE(sameBits(got.normalImpulse, want.normalImpulse)) << "point " << i;
            EXPECT_TRUE(sameBits(got.tangentImpulse1, want.tangentImpulse1)) << "point " << i;
            EXPECT_TRUE(sameBits(got.tangentImpulse2, want.tangentImpulse2)) << "point " << i;
            EXPECT_TRUE(sameBits(got.frictionShift, want.frictionShift)) << "point " << i;
            EXPECT_TRUE(sameBits(got.normalWork, want.normalWork)) << "point " << i;
            EXPECT_TRUE(sameBits(got.frictionWork, want.frictionWork)) << "point " << i;
        }
        for (std::size_t i = 0; i < oneByOne.size(); ++i) {
            for (int axis = 0; axis < 3; ++axis) {
                EXPECT_TRUE(sameBits(fourByFour[i].linearVelocity[axis],
                                     oneByOne[i].linearVelocity[axis]))
                    << "body " << i;
                EXPECT_TRUE(sameBits(fourByFour[i].angularVelocity[axis],
                                     oneByOne[i].angularVelocity[axis]))
                    << "body " << i;
            }
        }
        // the case worth checking: friction steps on the cone's edge, and bodies that moved
        EXPECT_GT(edgeSteps, reference.size() / 10);
        EXPECT_NE(oneByOne[0].linearVelocity, island.bodies[0].linearVelocity);
    }
}

TEST(LaneSweep, ASolveOfALargeIslandEndsAsTheSweepsOneAtATimeWould)
{
    // solveConstraints sweeps a coloured island four runs at a time from its second sweep: its
    // sweep count and maxima-driven stop are those of the same runs swept one point at a time
    const RandomIsland island(7, 300, 900);
    SweepSchedule schedule;
    scheduleSweeps(island.constraints, island.bodies, schedule);
    ASSERT_TRUE(schedule.coloured);
    std::vector<SolverBody> bodies = island.bodies;
    std::vector<ContactConstraint> constraints = island.constraints;
    const int sweeps = solveConstraints(constraints, bodies, schedule, 40, 1e-12, 0.0, 1);

    std::vector<SolverBody> oneByOne = island.bodies;
    std::vector<ContactConstraint> reference = island.constraints;
    int referenceSweeps = 40;
    for (int sweep = 1; sweep <= 40; ++sweep) {
        Real change = 0.0;
        Real impulse = 0.0;
        for (std::uint32_t colour = 0; colour <= schedule.colours.colourCount; ++colour) {
            for (const std::uint32_t run : schedule.colours.colour(colour)) {
                const std::uint32_t first = schedule.runStart[run];
                const std::uint32_t count = schedule.runStart[run + 1] - first;
                const std::span<ContactConstraint> points =
                    std::span(reference).subspan(first, count);
                std::vector<ContactConstraint> before(points.begin(), points.end());
                solveConstraints(points, oneByOne, 1, 0.0);
                for (std::uint32_t k = 0; k < count; ++k) {
                    const ContactConstraint& now = points[k];
                    const ContactConstraint& was = before[k];
                    change = std::max({change, std::abs(now.normalImpulse - was.normalImpulse),
                                       std::abs(now.tangentImpulse1 - was.tangentImpulse1),
                                       std::abs(now.tangentImpulse2 - was.tangentImpulse2)});
                    impulse = std::max({impulse, now.normalImpulse,
                                        std::sqrt(now.tangentImpulse1 * now.tangentImpulse1 +
                                                  now.tangentImpulse2 * now.tangentImpulse2)});
                }
            }
        }
        if (change <= 1e-12 * impulse) {
            referenceSweeps = sweep;
            break;
        }
    }
    EXPECT_EQ(sweeps, referenceSweeps);
    for (std::size_t i = 0; i < reference.size(); ++i) {
        EXPECT_TRUE(sameBits(constraints[i].normalImpulse, reference[i].normalImpulse)) << i;
        EXPECT_TRUE(sameBits(constraints[i].tangentImpulse1, reference[i].tangentImpulse1)) << i;
    }
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        EXPECT_TRUE(sameBits(bodies[i].linearVelocity.y, oneByOne[i].linearVelocity.y)) << i;
    }
}

} // namespace
} // namespace tumble
