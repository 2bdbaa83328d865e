// Sequential impulses over the contact points of an island of touching bodies: prepare, warm
// start, solve (docs/physics/11-island-solver.md).
#pragma once

#include "dynamics/constraint_colouring.hpp"
#include "dynamics/contact_constraint.hpp"

#include <span>

namespace tumble {

/// (11.5c): a solve over at least this many points sweeps colour by colour, whatever the number
/// of threads, so its result does not depend on that number; a smaller one keeps input order.
inline constexpr std::size_t kColouredSweepPoints = 1024;

/// What a constraint's target is for (11.4).
enum class ConstraintTarget : std::uint8_t {
    /// An impact: Newton's restitution target -e vn where the approach is faster than the
    /// threshold, else 0.
    Impact,
    /// A sub-step of length tau: 0 for a point in contact, -gap / tau for one still apart, so it
    /// may close the gap within the sub-step but not cross it (speculative contact).
    Substep,
};

struct ConstraintTargetSettings {
    ConstraintTarget target = ConstraintTarget::Substep;
    /// Sub-step length, s (for ConstraintTarget::Substep).
    Real tau = 0.0;
    /// A point with a gap at most this is in contact, m.
    Real touchingGap = 1e-4;
    /// Approach speeds below this get no restitution, m/s.
    Real restitutionThreshold = 0.05;
};

/// The tangent basis, Jacobian rows and effective masses (11.2), (11.3) of a constraint whose
/// normal and offsets are set, between bodies a and b: what depends on the geometry and the
/// inverse inertias only, so it holds for every solve until the bodies move.
void prepareConstraintGeometry(ContactConstraint& constraint, const SolverBody& a,
                               const SolverBody& b);

/// The velocity before the solve, friction coefficient (6.2) and target (11.4) of a constraint
/// whose geometry is prepared, from the bodies' velocities now. Keeps its impulses and starts
/// its work (8.2) from zero.
void prepareConstraintTargets(ContactConstraint& constraint, std::span<const SolverBody> bodies,
                              const ConstraintTargetSettings& settings);

/// prepareConstraintGeometry then prepareConstraintTargets, for a constraint whose bodies,
/// normal, offsets, gap and material are set.
void prepareConstraint(ContactConstraint& constraint, std::span<const SolverBody> bodies,
                       const ConstraintTargetSettings& settings);

/// prepareConstraintTargets for each constraint, those of a large island spread over `threads`.
void prepareConstraintTargets(std::span<ContactConstraint> constraints,
                              std::span<const SolverBody> bodies,
                              const ConstraintTargetSettings& settings, int threads);

/// (11.4a) Poisson's restitution after a compression solve: each point whose approach was fast
/// enough gets e times its compression impulse more, along the normal. Returns whether any
/// point got an impulse (none does when every such point has e = 0).
bool applyRestitution(std::span<ContactConstraint> constraints, std::span<SolverBody> bodies);

/// (11.5c) The order in which sweeps visit a set of constraints: input order below
/// kColouredSweepPoints points; above, runs of consecutive points of one pair of bodies (a
/// contact's manifold), coloured so that no colour moves a dynamic body twice. It depends only on
/// which bodies each constraint joins, so a warm start and the solve after it share one.
struct SweepSchedule {
    bool coloured = false;
    /// Run k is constraints [runStart[k], runStart[k + 1]).
    std::vector<std::uint32_t> runStart;
    ConstraintColours colours;
};

/// The schedule of sweeps over `constraints` (11.5c).
void scheduleSweeps(std::span<const ContactConstraint> constraints,
                    std::span<const SolverBody> bodies, SweepSchedule& schedule);

/// Applies the constraints' impulses to their bodies (warm starting, (11.6)).
/// Like solveConstraints, a large set of points is visited colour by colour, each colour over
/// `threads` threads, with the same result for any number of them.
void warmStart(std::span<ContactConstraint> constraints, std::span<SolverBody> bodies,
               int threads = 1);
/// warmStart in the order of a schedule made by scheduleSweeps for these constraints.
void warmStart(std::span<ContactConstraint> constraints, std::span<SolverBody> bodies,
               const SweepSchedule& schedule, int threads);

/// warmStart of kept constraints (11.6a): each point's impulses are first scaled by `scale`
/// (at most 1) and its friction put back in the cone of its coefficient (set with its targets),
/// in the same pass, as (11.6) starts from cached impulses.
void warmStartScaled(std::span<ContactConstraint> constraints, std::span<SolverBody> bodies,
                     const SweepSchedule& schedule, Real scale, int threads);

/// Gauss-Seidel sweeps of normal (11.4) then friction (11.5) impulses with accumulated clamping,
/// until no impulse changes by more than `convergence` times the largest, or no point's velocity
/// is corrected by more than `velocityTolerance` (m/s) in a sweep (11.5a), or `iterations`
/// sweeps. A solve of many points sweeps colour by colour, each colour over `threads` threads,
/// with the same result for any number of them (11.5c). Returns the sweeps done.
int solveConstraints(std::span<ContactConstraint> constraints, std::span<SolverBody> bodies,
                     int iterations, Real convergence, Real velocityTolerance = 0.0,
                     int threads = 1);
/// solveConstraints in the order of a schedule made by scheduleSweeps for these constraints.
int solveConstraints(std::span<ContactConstraint> constraints, std::span<SolverBody> bodies,
                     const SweepSchedule& schedule, int iterations, Real convergence,
                     Real velocityTolerance, int threads);

} // namespace tumble
