// kLanes manifolds of one colour (vector_lanes.hpp) solved side by side, one per vector lane
// (docs/physics/11-island-solver.md, (11.4), (11.5), (11.5d)).
#include "dynamics/wide_sweep.hpp"

#include "dynamics/vector_lanes.hpp"
#include "parallel_for.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace tumble {

namespace {

using namespace lanes;

/// One point slot of a block: lane j holds the k-th point of the block's j-th run, or nothing
/// (`active` clear, every field zero).
struct WidePoint {
    Wide3 normal, tangent1, tangent2;
    std::array<Wide3, 3> angularA, angularB, responseA, responseB;
    Wide normalMass, target, normalK;
    /// K_t and its inverse (11.3), row-major (a C array: std::array drops the alignment).
    Wide k[4];
    Wide mass[4];
    Wide friction, normalImpulse, impulse1, impulse2, shift, normalWork, frictionWork;
    Mask active;
};

/// kLanes runs of one colour: their bodies, and where their points are, packed and unpacked.
struct WideBlock {
    std::array<std::uint32_t, kLanes> bodyA{};
    std::array<std::uint32_t, kLanes> bodyB{};
    std::array<std::uint32_t, kLanes> begin{};
    std::array<std::uint32_t, kLanes> length{};
    std::uint32_t lanes = 0;
    std::size_t firstSlot = 0;
    std::uint32_t slots = 0;
};

/// The two bodies of each lane's run, in registers while the block's points are solved.
struct LaneBodies {
    Wide3 linearA, angularA, linearB, angularB;
    Wide invMassA, invMassB;
    Mask movesA, movesB;
};

/// The sweep's maxima (11.5a), lane by lane.
struct WideMaxima {
    Wide change = splat(0.0);
    Wide impulse = splat(0.0);
    Wide correction = splat(0.0);
};

/// Copies constraint c into lane `lane` of a point slot.
void packLane(WidePoint& p, int lane, const ContactConstraint& c)
{
    setLane(p.normal, lane, c.normal);
    setLane(p.tangent1, lane, c.tangent1);
    setLane(p.tangent2, lane, c.tangent2);
    for (int axis = 0; axis < 3; ++axis) {
        setLane(p.angularA[axis], lane, c.angularA[axis]);
        setLane(p.angularB[axis], lane, c.angularB[axis]);
        setLane(p.responseA[axis], lane, c.responseA[axis]);
        setLane(p.responseB[axis], lane, c.responseB[axis]);
    }
    p.normalMass[lane] = c.normalMass;
    p.target[lane] = c.targetNormalVelocity;
    // the sum (11.2) as the one-point step forms it
    p.normalK[lane] = c.normalKA + c.normalKB;
    for (int i = 0; i < 4; ++i) {
        p.k[i][lane] = c.tangentK[i];
        p.mass[i][lane] = c.tangentMass[i];
    }
    p.friction[lane] = c.friction;
    p.normalImpulse[lane] = c.normalImpulse;
    p.impulse1[lane] = c.tangentImpulse1;
    p.impulse2[lane] = c.tangentImpulse2;
    p.shift[lane] = c.frictionShift;
    p.normalWork[lane] = c.normalWork;
    p.frictionWork[lane] = c.frictionWork;
    p.active[lane] = -1;
}

/// applyAlong (point_impulses.hpp): `impulse` along direction d (index `axis`: n, t1, t2) on B
/// and its opposite on A, in the lanes where each body moves.
TUMBLE_WIDE_INLINE void applyAlong(const WidePoint& p, LaneBodies& bodies, Mask movesA,
                                   Mask movesB, const Wide3& direction, int axis, Wide impulse)
{
    pushAlong(bodies.linearA, bodies.invMassA * impulse, direction, movesA, false);
    pushAlong(bodies.angularA, impulse, p.responseA[axis], movesA, false);
    pushAlong(bodies.linearB, bodies.invMassB * impulse, direction, movesB, true);
    pushAlong(bodies.angularB, impulse, p.responseB[axis], movesB, true);
}

/// largest = max(largest, value) in the lanes of `active`.
TUMBLE_WIDE_INLINE void widen(Wide& largest, Wide value, Mask active)
{
    largest = maximum(largest, select(active, value, splat(0.0)));
}

/// solvePoint (constraint_sweeps.cpp) for one point slot of a block, in place.
TUMBLE_WIDE_INLINE void solveSlot(WidePoint& p, LaneBodies& bodies, WideMaxima& maxima)
{
    // no lambdas here: unoptimised, a lambda stays a function of the baseline target, and a
    // vector passed to it from a vector build's copy would arrive by another convention
    const Mask movesA = p.active & bodies.movesA;
    const Mask movesB = p.active & bodies.movesB;
    // (11.4): normal impulse with accumulated clamping
    const Wide normalA = dot(p.normal, bodies.linearA) + dot(p.angularA[0], bodies.angularA);
    const Wide normalB = dot(p.normal, bodies.linearB) + dot(p.angularB[0], bodies.angularB);
    const Wide normalImpulse =
        maximum(splat(0.0), p.normalImpulse + p.normalMass * (p.target - (normalB - normalA)));
    const Wide normalChange = normalImpulse - p.normalImpulse;
    p.normalImpulse = normalImpulse;
    applyAlong(p, bodies, movesA, movesB, p.normal, 0, normalChange);
    p.normalWork += normalChange * (normalB - normalA + splat(0.5) * normalChange * p.normalK);
    // (11.5): the friction step on the cone (6.4)
    const Wide tangential[4]{
        dot(p.tangent1, bodies.linearA) + dot(p.angularA[1], bodies.angularA),
        dot(p.tangent2, bodies.linearA) + dot(p.angularA[2], bodies.angularA),
        dot(p.tangent1, bodies.linearB) + dot(p.angularB[1], bodies.angularB),
        dot(p.tangent2, bodies.linearB) + dot(p.angularB[2], bodies.angularB)};
    Wide impulse1;
    Wide impulse2;
    frictionOnConeWide(p.k, p.mass, p.impulse1, p.impulse2, p.friction * normalImpulse,
                       tangential[2] - tangential[0], tangential[3] - tangential[1], p.shift,
                       impulse1, impulse2);
    const Wide change1 = impulse1 - p.impulse1;
    const Wide change2 = impulse2 - p.impulse2;
    p.impulse1 = impulse1;
    p.impulse2 = impulse2;
    applyAlong(p, bodies, movesA, movesB, p.tangent1, 1, change1);
    applyAlong(p, bodies, movesA, movesB, p.tangent2, 2, change2);
    const Wide along1 =
        tangential[2] - tangential[0] + splat(0.5) * (p.k[0] * change1 + p.k[1] * change2);
    const Wide along2 =
        tangential[3] - tangential[1] + splat(0.5) * (p.k[2] * change1 + p.k[3] * change2);
    p.frictionWork += change1 * along1 + change2 * along2;
    // the maxima of (11.5a), over the lanes that hold a point
    const Wide corrected1 = p.k[0] * change1 + p.k[1] * change2;
    const Wide corrected2 = p.k[2] * change1 + p.k[3] * change2;
    widen(maxima.change, absolute(normalChange), p.active);
    widen(maxima.change, absolute(change1), p.active);
    widen(maxima.change, absolute(change2), p.active);
    widen(maxima.impulse, normalImpulse, p.active);
    widen(maxima.impulse, squareRoot(impulse1 * impulse1 + impulse2 * impulse2), p.active);
    widen(maxima.correction, absolute(normalChange) / p.normalMass, p.active);
    widen(maxima.correction, squareRoot(corrected1 * corrected1 + corrected2 * corrected2),
          p.active);
}

Real largestLane(const Wide& w)
{
    Real largest = w[0];
    for (int lane = 1; lane < kLanes; ++lane) {
        largest = std::max(largest, w[lane]);
    }
    return largest;
}

} // namespace

struct LaneSweeps::Storage {
    std::vector<WideBlock> blocks;
    /// Colour c's blocks are [colourBlocks[c], colourBlocks[c + 1]).
    std::vector<std::size_t> colourBlocks;
    std::vector<WidePoint> points;
};

namespace {

/// LaneSweeps::sweep. On x86-64 with GCC it is compiled for AVX-512 and AVX2 (a lane to
/// each of the doubles of a register) and for the baseline, and the loader picks the one
/// the processor runs; all give the same bits, since none fuses a multiply and an add.
TUMBLE_WIDE_CLONES
void sweepBlocks(std::span<const WideBlock> blocks, std::span<WidePoint> points,
                 std::span<SolverBody> bodies, WideMaxima& wide)
{
    const SolverBody none;
    for (const WideBlock& block : blocks) {
        std::array<const SolverBody*, kLanes> a{};
        std::array<const SolverBody*, kLanes> b{};
        a.fill(&none);
        b.fill(&none);
        for (std::uint32_t lane = 0; lane < block.lanes; ++lane) {
            a[lane] = &bodies[block.bodyA[lane]];
            b[lane] = &bodies[block.bodyB[lane]];
        }
        LaneBodies state;
        for (int lane = 0; lane < kLanes; ++lane) {
            setLane(state.linearA, lane, a[lane]->linearVelocity);
            setLane(state.angularA, lane, a[lane]->angularVelocity);
            setLane(state.linearB, lane, b[lane]->linearVelocity);
            setLane(state.angularB, lane, b[lane]->angularVelocity);
            state.invMassA[lane] = a[lane]->invMass;
            state.invMassB[lane] = b[lane]->invMass;
        }
        // isFixed: the static geometry (zero inverse mass) is never written
        state.movesA = ~__builtin_bit_cast(Mask, state.invMassA == splat(0.0));
        state.movesB = ~__builtin_bit_cast(Mask, state.invMassB == splat(0.0));
        for (std::uint32_t k = 0; k < block.slots; ++k) {
            solveSlot(points[block.firstSlot + k], state, wide);
        }
        for (std::uint32_t lane = 0; lane < block.lanes; ++lane) {
            const auto l = static_cast<int>(lane);
            if (state.movesA[lane] != 0) {
                bodies[block.bodyA[lane]].linearVelocity = laneOf(state.linearA, l);
                bodies[block.bodyA[lane]].angularVelocity = laneOf(state.angularA, l);
            }
            if (state.movesB[lane] != 0) {
                bodies[block.bodyB[lane]].linearVelocity = laneOf(state.linearB, l);
                bodies[block.bodyB[lane]].angularVelocity = laneOf(state.angularB, l);
            }
        }
    }
}

} // namespace

LaneSweeps::LaneSweeps() : m_storage(std::make_unique<Storage>()) {}

LaneSweeps::~LaneSweeps() = default;

void LaneSweeps::pack(const SweepSchedule& schedule,
                          std::span<const ContactConstraint> constraints, int threads)
{
    Storage& storage = *m_storage;
    storage.blocks.clear();
    storage.colourBlocks.assign(1, 0);
    std::size_t slots = 0;
    const ConstraintColours& colours = schedule.colours;
    for (std::uint32_t colour = 0; colour < colours.colourCount; ++colour) {
        const std::span<const std::uint32_t> runs = colours.colour(colour);
        for (std::size_t first = 0; first < runs.size(); first += kLanes) {
            WideBlock& block = storage.blocks.emplace_back();
            block.lanes =
                static_cast<std::uint32_t>(std::min<std::size_t>(kLanes, runs.size() - first));
            block.firstSlot = slots;
            for (std::uint32_t lane = 0; lane < block.lanes; ++lane) {
                const std::uint32_t run = runs[first + lane];
                block.begin[lane] = schedule.runStart[run];
                block.length[lane] = schedule.runStart[run + 1] - schedule.runStart[run];
                block.bodyA[lane] = constraints[block.begin[lane]].bodyA;
                block.bodyB[lane] = constraints[block.begin[lane]].bodyB;
                block.slots = std::max(block.slots, block.length[lane]);
            }
            slots += block.slots;
        }
        storage.colourBlocks.push_back(storage.blocks.size());
    }
    storage.points.resize(slots);
    // each block writes only its own slots
    parallelFor(storage.blocks.size(), threads, [&](std::size_t b) {
        const WideBlock& block = storage.blocks[b];
        for (std::uint32_t k = 0; k < block.slots; ++k) {
            storage.points[block.firstSlot + k] = WidePoint{};
        }
        for (std::uint32_t lane = 0; lane < block.lanes; ++lane) {
            for (std::uint32_t k = 0; k < block.length[lane]; ++k) {
                packLane(storage.points[block.firstSlot + k], static_cast<int>(lane),
                         constraints[block.begin[lane] + k]);
            }
        }
    });
}

std::pair<std::size_t, std::size_t> LaneSweeps::blocksOf(std::uint32_t colour) const
{
    return {m_storage->colourBlocks[colour], m_storage->colourBlocks[colour + 1]};
}

void LaneSweeps::sweep(std::size_t first, std::size_t last, std::span<SolverBody> bodies,
                           SweepMaxima& maxima)
{
    WideMaxima wide;
    sweepBlocks(std::span<const WideBlock>(m_storage->blocks).subspan(first, last - first),
                m_storage->points, bodies, wide);
    maxima.change = std::max(maxima.change, largestLane(wide.change));
    maxima.impulse = std::max(maxima.impulse, largestLane(wide.impulse));
    maxima.correction = std::max(maxima.correction, largestLane(wide.correction));
}

void LaneSweeps::unpack(std::span<ContactConstraint> constraints, int threads) const
{
    const Storage& storage = *m_storage;
    // each block's runs are its own constraints
    parallelFor(storage.blocks.size(), threads, [&](std::size_t b) {
        const WideBlock& block = storage.blocks[b];
        for (std::uint32_t lane = 0; lane < block.lanes; ++lane) {
            for (std::uint32_t k = 0; k < block.length[lane]; ++k) {
                const WidePoint& p = storage.points[block.firstSlot + k];
                ContactConstraint& c = constraints[block.begin[lane] + k];
                c.normalImpulse = p.normalImpulse[lane];
                c.tangentImpulse1 = p.impulse1[lane];
                c.tangentImpulse2 = p.impulse2[lane];
                c.frictionShift = p.shift[lane];
                c.normalWork = p.normalWork[lane];
                c.frictionWork = p.frictionWork[lane];
            }
        }
    });
}

} // namespace tumble
