// A sweep's point steps over several manifolds at once: the runs of one colour share no dynamic
// body, so kLanes of them (four, or eight with AVX-512) are solved side by side in the lanes of
// one vector, each lane doing exactly the arithmetic of the one-point step
// (docs/physics/11-island-solver.md, (11.5d)).
#pragma once

#include "dynamics/contact_constraint.hpp"
#include "dynamics/island_solver.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace tumble {

/// The largest impulse change, impulse and velocity correction of a sweep (11.5a).
struct SweepMaxima {
    Real change = 0.0;
    Real impulse = 0.0;
    Real correction = 0.0;
};

/// The colours of a coloured schedule (11.5c) packed kLanes runs to a block, each block's points
/// lane by lane in memory (structure of arrays), for sweeps that solve the runs of a block
/// side by side. The overflow group is not packed: it is swept one point at a time.
class LaneSweeps {
public:
    LaneSweeps();
    ~LaneSweeps();
    LaneSweeps(const LaneSweeps&) = delete;
    LaneSweeps& operator=(const LaneSweeps&) = delete;

    /// Copies the constraints of the schedule's colours, impulses and work included, the blocks
    /// spread over `threads`.
    void pack(const SweepSchedule& schedule, std::span<const ContactConstraint> constraints,
              int threads = 1);

    /// The blocks of colour `colour`: [first, last).
    [[nodiscard]] std::pair<std::size_t, std::size_t> blocksOf(std::uint32_t colour) const;

    /// The normal (11.4) then friction (11.5) step of every point of blocks [first, last) of
    /// one colour, each run's points in order. The velocities, impulses and work are bit for bit
    /// those of the one-point step over the runs one after the other: each lane rounds as that
    /// step does (no fused operations), and the runs of a colour move disjoint bodies. Widens
    /// `maxima`.
    void sweep(std::size_t first, std::size_t last, std::span<SolverBody> bodies,
               SweepMaxima& maxima);

    /// Writes the impulses, friction shifts and work back to the constraints packed, the blocks
    /// spread over `threads`.
    void unpack(std::span<ContactConstraint> constraints, int threads = 1) const;

private:
    struct Storage;
    std::unique_ptr<Storage> m_storage;
};

} // namespace tumble
