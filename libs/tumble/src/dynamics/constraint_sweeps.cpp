// Gauss-Seidel sweeps over an island's contact points, in input order for a small island and
// colour by colour for a large one, whose colours spread over threads
// (docs/physics/11-island-solver.md, (11.4), (11.5), (11.5a), (11.5c), (11.5e)).
#include "dynamics/active_set_step.hpp"
#include "dynamics/constraint_colouring.hpp"
#include "dynamics/friction_cone.hpp"
#include "dynamics/island_solver.hpp"
#include "dynamics/point_impulses.hpp"
#include "dynamics/wide_sweep.hpp"
#include "parallel_for.hpp"

#include <algorithm>
#include <cmath>

#ifdef TUMBLE_HAVE_OPENMP
#include <omp.h>
#endif

namespace tumble {

namespace {

/// (11.5c): the threads share a coloured sweep only when each has at least this many runs of a
/// colour on average: a colour ends at a barrier, which smaller shares would not pay for. The
/// result is the same either way.
constexpr std::size_t kRunsPerThread = 32;
/// (11.5e): sweeps between the steps on the active rows of an input-order solve, and the
/// conjugate-gradient iterations of one; all the steps of a solve take at most eight times as
/// many iterations as it may take sweeps, each about the price of a sweep, so a solve that the
/// steps do not bring to an end costs at most about nine times what its sweeps cost (a column of
/// 20 landing cube by cube needs that much: at four times it does not settle).
constexpr int kActiveSetPeriod = 8;
constexpr int kActiveSetIterations = 256;

/// One point's normal step (11.4) then friction step (11.5), with accumulated clamping.
void solvePoint(ContactConstraint& c, SolverBody& a, SolverBody& b, SweepMaxima& maxima)
{
    // (11.4): normal impulse with accumulated clamping, lambda_n >= 0
    const Real normalA = pointVelocityAlong(a, c.normal, c.angularA[0]);
    const Real normalB = pointVelocityAlong(b, c.normal, c.angularB[0]);
    const Real normalImpulse = std::max(
        0.0, c.normalImpulse + c.normalMass * (c.targetNormalVelocity - (normalB - normalA)));
    const Real normalChange = normalImpulse - c.normalImpulse;
    c.normalImpulse = normalImpulse;
    applyNormal(c, a, b, normalChange, normalA, normalB);
    // (11.5): the friction step of maximal dissipation on the cone (6.4)
    const std::array<Real, 4> tangential{pointVelocityAlong(a, c.tangent1, c.angularA[1]),
                                         pointVelocityAlong(a, c.tangent2, c.angularA[2]),
                                         pointVelocityAlong(b, c.tangent1, c.angularB[1]),
                                         pointVelocityAlong(b, c.tangent2, c.angularB[2])};
    const FrictionImpulse friction =
        frictionOnCone(c.tangentK, c.tangentMass, c.tangentImpulse1, c.tangentImpulse2,
                       c.friction * c.normalImpulse, tangential[2] - tangential[0],
                       tangential[3] - tangential[1], c.frictionShift);
    const Real impulse1 = friction.impulse1;
    const Real impulse2 = friction.impulse2;
    const Real change1 = impulse1 - c.tangentImpulse1;
    const Real change2 = impulse2 - c.tangentImpulse2;
    c.tangentImpulse1 = impulse1;
    c.tangentImpulse2 = impulse2;
    applyFriction(c, a, b, change1, change2, tangential);
    maxima.change = std::max(
        {maxima.change, std::abs(normalChange), std::abs(change1), std::abs(change2)});
    maxima.impulse = std::max(
        {maxima.impulse, normalImpulse, std::sqrt(impulse1 * impulse1 + impulse2 * impulse2)});
    // the velocity the step put right, |K delta lambda| (11.5a)
    const Real tangential1 = c.tangentK[0] * change1 + c.tangentK[1] * change2;
    const Real tangential2 = c.tangentK[2] * change1 + c.tangentK[3] * change2;
    maxima.correction =
        std::max({maxima.correction, std::abs(normalChange) / c.normalMass,
                  std::sqrt(tangential1 * tangential1 + tangential2 * tangential2)});
}

/// The first point of each run of consecutive points of one pair of bodies, and the pairs.
void findRuns(std::span<const ContactConstraint> constraints, SweepSchedule& schedule,
              std::vector<ProxyPair>& runBodies)
{
    schedule.runStart.clear();
    runBodies.clear();
    for (std::size_t i = 0; i < constraints.size(); ++i) {
        const ContactConstraint& c = constraints[i];
        if (i == 0 || c.bodyA != constraints[i - 1].bodyA ||
            c.bodyB != constraints[i - 1].bodyB) {
            schedule.runStart.push_back(static_cast<std::uint32_t>(i));
            runBodies.push_back({c.bodyA, c.bodyB});
        }
    }
    schedule.runStart.push_back(static_cast<std::uint32_t>(constraints.size()));
}

/// A pass colour by colour (11.5c): `item(colour, k, maxima)` for the `count(colour)` items of
/// each colour, then `overflow(maxima)`. The items of a colour share no dynamic body, so they
/// are split over the threads, with the same velocities and impulses as on one, when each
/// thread gets kRunsPerThread runs of a colour on average; a colour ends at a barrier.
template <typename Count, typename Item, typename Overflow>
SweepMaxima byColour(const SweepSchedule& schedule, int threads, const Count& count,
                     const Item& item, const Overflow& overflow)
{
    const ConstraintColours& colours = schedule.colours;
    const std::size_t runCount = schedule.runStart.size() - 1;
    if (threads <= 1 ||
        runCount < kRunsPerThread * static_cast<std::size_t>(threads) * colours.colourCount) {
        SweepMaxima maxima;
        for (std::uint32_t colour = 0; colour < colours.colourCount; ++colour) {
            for (std::size_t k = 0; k < count(colour); ++k) {
                item(colour, k, maxima);
            }
        }
        overflow(maxima);
        return maxima;
    }
    Real change = 0.0;
    Real impulse = 0.0;
    Real correction = 0.0;
#ifdef TUMBLE_HAVE_OPENMP
#pragma omp parallel num_threads(threads) reduction(max : change, impulse, correction)
#endif
    {
        SweepMaxima mine;
        for (std::uint32_t colour = 0; colour < colours.colourCount; ++colour) {
            const auto items = static_cast<std::ptrdiff_t>(count(colour));
#ifdef TUMBLE_HAVE_OPENMP
#pragma omp for schedule(static)
#endif
            for (std::ptrdiff_t k = 0; k < items; ++k) {
                item(colour, static_cast<std::size_t>(k), mine);
            }
        }
#ifdef TUMBLE_HAVE_OPENMP
#pragma omp single
#endif
        overflow(mine);
        change = std::max(change, mine.change);
        impulse = std::max(impulse, mine.impulse);
        correction = std::max(correction, mine.correction);
    }
    return {change, impulse, correction};
}

/// The points of the given runs, each run's in order, `step(c, a, b, maxima)` at each.
template <typename PointStep>
void stepRuns(const SweepSchedule& schedule, std::span<const std::uint32_t> runs,
              std::span<ContactConstraint> constraints, std::span<SolverBody> bodies,
              SweepMaxima& maxima, const PointStep& step)
{
    for (const std::uint32_t run : runs) {
        for (std::uint32_t i = schedule.runStart[run]; i < schedule.runStart[run + 1]; ++i) {
            ContactConstraint& c = constraints[i];
            step(c, bodies[c.bodyA], bodies[c.bodyB], maxima);
        }
    }
}

/// One pass colour by colour, `step(c, a, b, maxima)` at each point of each run in turn.
template <typename PointStep>
SweepMaxima colouredPass(const SweepSchedule& schedule, std::span<ContactConstraint> constraints,
                         std::span<SolverBody> bodies, int threads, const PointStep& step)
{
    const ConstraintColours& colours = schedule.colours;
    return byColour(
        schedule, threads, [&](std::uint32_t colour) { return colours.colour(colour).size(); },
        [&](std::uint32_t colour, std::size_t k, SweepMaxima& maxima) {
            stepRuns(schedule, colours.colour(colour).subspan(k, 1), constraints, bodies, maxima,
                     step);
        },
        [&](SweepMaxima& maxima) {
            stepRuns(schedule, colours.overflow(), constraints, bodies, maxima, step);
        });
}

/// One sweep colour by colour from the packed copy of the colours (11.5d): each colour's blocks
/// of kLanes runs, then the overflow group one point at a time. The same velocities and impulses
/// as colouredPass with solvePoint.
SweepMaxima colouredSweep(const SweepSchedule& schedule, LaneSweeps& packed,
                          std::span<ContactConstraint> constraints, std::span<SolverBody> bodies,
                          int threads)
{
    return byColour(
        schedule, threads,
        [&](std::uint32_t colour) {
            const auto [first, last] = packed.blocksOf(colour);
            return last - first;
        },
        [&](std::uint32_t colour, std::size_t k, SweepMaxima& maxima) {
            const std::size_t block = packed.blocksOf(colour).first + k;
            packed.sweep(block, block + 1, bodies, maxima);
        },
        [&](SweepMaxima& maxima) {
            stepRuns(schedule, schedule.colours.overflow(), constraints, bodies, maxima,
                     solvePoint);
        });
}

} // namespace

void scheduleSweeps(std::span<const ContactConstraint> constraints,
                    std::span<const SolverBody> bodies, SweepSchedule& schedule)
{
    schedule.coloured = constraints.size() >= kColouredSweepPoints;
    if (!schedule.coloured) {
        return;
    }
    std::vector<ProxyPair> runBodies;
    findRuns(constraints, schedule, runBodies);
    std::vector<std::uint8_t> fixed(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        fixed[i] = isFixed(bodies[i]) ? 1 : 0;
    }
    schedule.colours = colourConstraints(runBodies, fixed, kMaxConstraintColours);
}

int solveConstraints(std::span<ContactConstraint> constraints, std::span<SolverBody> bodies,
                     int iterations, Real convergence, Real velocityTolerance, int threads)
{
    SweepSchedule schedule;
    scheduleSweeps(constraints, bodies, schedule);
    return solveConstraints(constraints, bodies, schedule, iterations, convergence,
                            velocityTolerance, threads);
}

int solveConstraints(std::span<ContactConstraint> constraints, std::span<SolverBody> bodies,
                     const SweepSchedule& schedule, int iterations, Real convergence,
                     Real velocityTolerance, int threads)
{
    // (11.5d): a coloured solve not done after its first sweep goes on from a packed copy of
    // its colours, a block of runs side by side; a settled island's one sweep does not pay for
    // the copy
    thread_local LaneSweeps packed;
    bool isPacked = false;
    int sweeps = iterations;
    bool activeSetHelps = true;
    int activeSetBudget = 8 * iterations;
    for (int sweep = 1; sweep <= iterations; ++sweep) {
        SweepMaxima maxima;
        if (schedule.coloured && sweep > 1) {
            if (!isPacked) {
                packed.pack(schedule, constraints, threads);
                isPacked = true;
            }
            maxima = colouredSweep(schedule, packed, constraints, bodies, threads);
        } else if (schedule.coloured) {
            maxima = colouredPass(schedule, constraints, bodies, threads, solvePoint);
        } else {
            for (ContactConstraint& c : constraints) {
                solvePoint(c, bodies[c.bodyA], bodies[c.bodyB], maxima);
            }
        }
        if (maxima.change <= convergence * maxima.impulse ||
            maxima.correction <= velocityTolerance) {
            sweeps = sweep;
            break;
        }
        // (11.5e): every kActiveSetPeriod sweeps of an input-order solve, the rows found active
        // together, until such a step fails to lower the objective
        if (!schedule.coloured && sweep % kActiveSetPeriod == 0 && sweep < iterations &&
            activeSetHelps && activeSetBudget > 0) {
            activeSetHelps =
                stepOnActiveSet(constraints, bodies, kActiveSetIterations, activeSetBudget,
                                velocityTolerance);
        }
    }
    if (isPacked) {
        packed.unpack(constraints, threads);
    }
    return sweeps;
}

void warmStart(std::span<ContactConstraint> constraints, std::span<SolverBody> bodies,
               int threads)
{
    SweepSchedule schedule;
    scheduleSweeps(constraints, bodies, schedule);
    warmStart(constraints, bodies, schedule, threads);
}

void warmStart(std::span<ContactConstraint> constraints, std::span<SolverBody> bodies,
               const SweepSchedule& schedule, int threads)
{
    if (!schedule.coloured) {
        for (ContactConstraint& c : constraints) {
            warmStartPoint(c, bodies[c.bodyA], bodies[c.bodyB]);
        }
        return;
    }
    // in the order of the sweeps (11.5c), each colour over the threads
    colouredPass(schedule, constraints, bodies, threads,
                 [](ContactConstraint& c, SolverBody& a, SolverBody& b, SweepMaxima&) {
                     warmStartPoint(c, a, b);
                 });
}

void warmStartScaled(std::span<ContactConstraint> constraints, std::span<SolverBody> bodies,
                     const SweepSchedule& schedule, Real scale, int threads)
{
    const auto startAndApply = [scale](ContactConstraint& c, SolverBody& a, SolverBody& b,
                                       SweepMaxima&) {
        startInCone(c, scale * c.normalImpulse, scale * c.tangentImpulse1,
                    scale * c.tangentImpulse2);
        warmStartPoint(c, a, b);
    };
    if (!schedule.coloured) {
        SweepMaxima unused;
        for (ContactConstraint& c : constraints) {
            startAndApply(c, bodies[c.bodyA], bodies[c.bodyB], unused);
        }
        return;
    }
    colouredPass(schedule, constraints, bodies, threads, startAndApply);
}

void prepareConstraintTargets(std::span<ContactConstraint> constraints,
                              std::span<const SolverBody> bodies,
                              const ConstraintTargetSettings& settings, int threads)
{
    // each constraint reads the bodies and writes only itself
    parallelFor(constraints.size(), constraints.size() >= kColouredSweepPoints ? threads : 1,
                [&](std::size_t i) { prepareConstraintTargets(constraints[i], bodies, settings); });
}

} // namespace tumble
