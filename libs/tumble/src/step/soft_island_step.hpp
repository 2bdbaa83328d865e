// The soft step of one island as its passes (docs/physics/12-soft-step.md): the class the
// step's files share; advanceSoft (step/soft_step.hpp) runs it.
#pragma once

#include "body_slot.hpp"
#include "dynamics/energy_booking.hpp"
#include "parallel_for.hpp"
#include "step/coupled_step.hpp"
#include "step/soft_buffers.hpp"
#include "step/step_context.hpp"
#include "step/step_events.hpp"

#include <array>
#include <span>
#include <utility>

namespace tumble {

/// One island's soft step over dt: its manifolds built (or kept), the sub-steps, restitution,
/// and the bodies and warm-start caches written back.
class SoftStep {
public:
    /// With `kept`, `buffers` hold the island's manifolds of its last step (12.5b).
    SoftStep(const CoupledIsland& island, std::span<BodySlot> slots, const StepContext& context,
             StepEvents& events, SoftBuffers& buffers, bool kept)
        : m_island(island), m_slots(slots), m_context(context), m_settings(context.settings),
          m_events(events), m_buffers(buffers), m_kept(kept)
    {
    }

    void run(Real dt);

private:
    void prepare(Real dt);
    /// Each body's start of the step; a kept island's bodies start where they moved to since
    /// its manifolds were built (12.5b).
    void startBodies();
    /// The work of the island's impulses over the step, in a fixed order (the lanes' blocks,
    /// then the manifolds not packed), and in `m_buffers.touching` each body one of whose
    /// points pushed in the last sub-step (7.1).
    IslandWork gatherWork();
    /// One sub-step; `bookLast` when a sub-step went before it (its work is booked here).
    void substep(Real h, const SoftSolveSettings& solve, bool bookLast);
    void finish();
    /// For each body, in one pass: with `bookWork`, adds to its work what its kinetic energy
    /// gained since `m_buffers.kinetic` (the passes' work since the last call); then gravity
    /// over h (none for h = 0); then keeps its kinetic energy in `m_buffers.kinetic`.
    void bookWorkAndGravity(Real h, bool bookWork);
    /// bookWorkAndGravity's work for body i.
    void bookBody(std::size_t i, Real h, bool bookWork);
    /// (12.4): body i's position and orientation advanced over h with its solved velocities.
    void advancePose(std::size_t i, Real h);
    /// Whether the sub-steps run in one parallel region (substepsInOneTeam): an island split
    /// in halves (12.9), all of its manifolds in lanes, on several threads.
    [[nodiscard]] bool substepsInOneTeam() const;
    /// The sub-steps of substep and the restitution after them, every pass in one parallel
    /// region, each thread sweeping its half's bodies and colours, the threads meeting at a
    /// spinning barrier between passes: the same passes in the same order, so the same bits.
    void substepsInOneTeam(Real h, const SoftSolveSettings& solve, int substeps);
    Body& body(std::size_t local) { return m_slots[m_island.bodies[local]].body; }
    /// visit(i) for each of the island's bodies, each half of a split island on the thread that
    /// sweeps its colours (12.9); each call writes only body i's entries.
    template <typename Visit>
    void forEachBody(const Visit& visit)
    {
        parallelForSplit(m_island.bodies.size(), m_buffers.order.colours.halfSplit,
                         m_context.threads, visit);
    }

    /// The sums of term(i) = {x_i, y_i} over the island's bodies: a split island's halves
    /// (12.9) each summed in order on the thread forEachBody gives them, then the first half's
    /// sum plus the second's, so the bits depend on the island alone.
    template <typename Term>
    std::pair<Real, Real> sumOverHalves(const Term& term)
    {
        const std::size_t count = m_island.bodies.size();
        const std::size_t split = m_buffers.order.colours.halfSplit;
        const bool halves = split > 0 && split < count;
        std::array<std::pair<Real, Real>, 2> sums{};
        const auto sumHalf = [&](std::size_t half) {
            const auto [first, last] = splitShare(count, halves ? split : count, half, 2);
            for (std::size_t i = first; i < last; ++i) {
                const auto [x, y] = term(i);
                sums[half].first += x;
                sums[half].second += y;
            }
        };
        if (halves && m_context.threads > 1) {
            parallelPhases(1, 2, [&](std::size_t, std::size_t share, std::size_t shares) {
                for (std::size_t half = share; half < 2; half += shares) {
                    sumHalf(half);
                }
            });
        } else {
            sumHalf(0);
            sumHalf(1);
        }
        return {sums[0].first + sums[1].first, sums[0].second + sums[1].second};
    }

    const CoupledIsland& m_island;
    std::span<BodySlot> m_slots;
    const StepContext& m_context;
    const WorldSettings& m_settings;
    StepEvents& m_events;
    SoftBuffers& m_buffers;
    bool m_kept;
};

} // namespace tumble
