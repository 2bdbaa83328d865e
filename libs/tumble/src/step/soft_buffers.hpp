#pragma once

// What an island's soft step works in: a thread's set while it builds an island's manifolds,
// then the island's own while they are kept (soft_step.cpp, (12.5b)).

#include "dynamics/energy_booking.hpp"
#include "dynamics/soft_contact_solver.hpp"
#include "dynamics/soft_lanes.hpp"
#include "dynamics/solver_point.hpp"
#include "step/island_contacts.hpp"
#include "step/soft_contact_order.hpp"
#include "step/soft_warm_start.hpp"

#include <utility>
#include <vector>

namespace tumble {

/// The vectors of an island's soft step.
struct SoftBuffers {
    /// The island's contacts in the narrow phase's order, owner after owner.
    std::vector<IslandContact> contacts;
    std::vector<Vec3> centres;
    /// The manifolds of the overflow group from its first, or of every contact of an island
    /// not in lanes.
    std::vector<SoftManifold> manifolds;
    /// softResultOf of each manifold, in colour order, gathered for the warm-start store
    /// (collectSoftResults).
    std::vector<SoftContactResult> results;
    /// With lanes, the work of each block (SoftLanes::work); and 1 for each manifold, in
    /// colour order, a point of which pushed in the last sub-step.
    std::vector<SoftBlockWork> blockWork;
    std::vector<std::uint8_t> pushed;
    SoftContactOrder order;
    /// Each manifold's static and kinetic friction coefficients, in colour order.
    std::vector<std::pair<Real, Real>> frictions;
    SoftLanes lanes;
    /// Whether this step's colours are packed in `lanes`.
    bool inLanes = false;
    /// What each contact's owner kept of it, in the contacts' order.
    std::vector<KeptImpulses> kept;
    std::vector<SoftBody> bodies;
    /// Each body's mass, inertia and orientation at the step's start, and that orientation's
    /// rotation transposed, R0^T: what the sub-steps read of the body (the world's copy stays
    /// at the step's start until finish).
    std::vector<InertialFrame> frames;
    std::vector<Mat3> startRotationsT;
    std::vector<Quat> startOrientations;
    /// The contact points of the island's manifolds.
    std::size_t points = 0;
    std::vector<Real> energies;
    std::vector<Real> kineticStart;
    std::vector<Real> bodyWork;
    std::vector<Real> kinetic;
    /// Whether a point of the body's pushed in the last sub-step (7.1), gathered from the
    /// contacts before the bodies' pass writes it to their slots.
    std::vector<std::uint8_t> touching;
};

} // namespace tumble
