// The soft step's passes over several manifolds at once: the manifolds of one colour share no
// dynamic body, so kLanes of them (four, or eight with AVX-512) are solved side by side in the
// lanes of one vector, each lane doing exactly the arithmetic of the one-manifold pass
// (docs/physics/12-soft-step.md, (12.9)).
#pragma once

#include "dynamics/soft_contact_solver.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace tumble {

class PhaseTeam;

/// The normal and friction work of one block's manifolds over a step, J.
struct SoftBlockWork {
    Real normal = 0.0;
    Real friction = 0.0;
};

/// The colours of a soft island (not the overflow group) packed kLanes manifolds to a block, each
/// block lane by lane in memory (structure of arrays).
class SoftLanes {
public:
    SoftLanes();
    ~SoftLanes();
    /// A copy holds its own blocks (a World copied keeps its islands' kept lanes, (12.5b)).
    SoftLanes(const SoftLanes& other);
    SoftLanes& operator=(const SoftLanes& other);

    /// The manifolds of one block: kLanes of the library's build (vector_lanes.hpp).
    static std::size_t manifoldsPerBlock();

    /// The manifold of a contact, by its index in colour order.
    using ManifoldSource = std::function<SoftManifold(std::size_t)>;

    /// Packs the manifolds `source` gives for every colour but the overflow, their points,
    /// centres and impulses, and builds their rows in the lanes from the inverse masses and
    /// inertias of `bodies` (whose last entry is the static body): the rows of prepareSoftRows,
    /// bit for bit, which the source need not have built. The blocks are spread over `threads`;
    /// each manifold is asked for once, on the thread that packs it, so that a large island's
    /// manifolds need not be kept anywhere else.
    void pack(const ManifoldSource& source, const SoftColours& colours,
              std::span<const SoftBody> bodies, int threads);
    /// The same from manifolds kept.
    void pack(std::span<const SoftManifold> manifolds, const SoftColours& colours,
              std::span<const SoftBody> bodies, int threads);

    /// restartSoftManifold on every manifold packed, from the velocities of `bodies` and each
    /// manifold's static and kinetic friction coefficients in `frictions` (by its index in
    /// colour order): the lanes kept from the last step start this one (12.5b). The blocks are
    /// spread over `threads`.
    void restart(std::span<const SoftBody> bodies,
                 std::span<const std::pair<Real, Real>> frictions, int threads);

    /// warmStartSoft over the colours' manifolds, colour after colour, a large colour shared
    /// over `threads`.
    void warmStart(std::span<SoftBody> bodies, int threads);

    /// solveSoft over the colours' manifolds, bit for bit: each lane rounds as the
    /// one-manifold pass does (no fused operations), and a colour's manifolds move disjoint
    /// bodies.
    void solve(std::span<SoftBody> bodies, const SoftSolveSettings& settings, bool useBias,
               int threads);

    /// warmStart and solve by the threads of a team already running (parallelTeam), each
    /// calling them: the colours' phases meet at the team's barrier, and no region is started.
    void warmStart(std::span<SoftBody> bodies, const PhaseTeam& team);
    void solve(std::span<SoftBody> bodies, const SoftSolveSettings& settings, bool useBias,
               const PhaseTeam& team);

    /// restituteSoft over the colours' manifolds: each lane of elasticity other than zero
    /// through restituteManifold, so the bits are those of the manifold alone.
    void restitute(std::span<SoftBody> bodies, Real threshold, int threads);
    /// The same by the threads of a team already running, as warmStart and solve.
    void restitute(std::span<SoftBody> bodies, Real threshold, const PhaseTeam& team);

    /// Writes the impulses and work back to the manifolds packed, the blocks over `threads`.
    void unpack(std::span<SoftManifold> manifolds, int threads) const;

    /// softResultOf for each manifold packed, into its index in `results`.
    void results(std::span<SoftContactResult> results, int threads) const;

    /// The work of each block's impulses, into `blockWork` (an entry a block, in the blocks'
    /// order): its lanes in order, each lane's points' normal work then its friction work; and
    /// 1 in `pushed`, at its index in colour order, for each manifold a point of which pushes.
    /// The blocks are spread over `threads`, each on the thread that sweeps it.
    void work(std::vector<SoftBlockWork>& blockWork, std::span<std::uint8_t> pushed,
              int threads) const;

private:
    struct Storage;
    std::unique_ptr<Storage> m_storage;
};

} // namespace tumble
