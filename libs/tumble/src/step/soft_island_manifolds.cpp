// A soft island's manifolds, built or kept (docs/physics/12-soft-step.md, (12.5b), (12.9)).
#include "step/soft_island_manifolds.hpp"

#include "parallel_for.hpp"
#include "prefetch.hpp"
#include "step/coupled_step.hpp"
#include "step/soft_buffers.hpp"
#include "step/soft_manifolds.hpp"

#include <utility>
#include <vector>

namespace tumble {

namespace {

/// An island of fewer manifolds sweeps them one at a time: most lanes of its colours' blocks
/// would be empty.
constexpr std::size_t kLaneManifolds = 32;
/// How many manifolds ahead of the one being built its contact is asked for (prefetch.hpp).
constexpr std::size_t kLanesPrefetchedAhead = 8;

/// (12.3) and (12.5): the manifold of the contact k-th in colour order, started from its
/// owner's kept impulses; its rows only with `rows` (SoftLanes builds them as it packs). Writes
/// its friction coefficients to `buffers.frictions[k]`.
SoftManifold manifoldOf(SoftBuffers& buffers, std::size_t staticIndex, std::size_t k, bool rows)
{
    const std::vector<std::uint32_t>& order = buffers.order.colourOrder;
    // the contacts are read in colour order, all over memory: the next block's asked for ahead
    if (k + kLanesPrefetchedAhead < order.size()) {
        const std::uint32_t next = order[k + kLanesPrefetchedAhead];
        prefetchLines(&buffers.contacts[next], sizeof(IslandContact));
        prefetchLines(&buffers.kept[next], sizeof(KeptImpulses));
    }
    const std::uint32_t contact = order[k];
    buffers.frictions[k] = {buffers.contacts[contact].staticFriction,
                            buffers.contacts[contact].friction};
    SoftManifold m = softManifoldOf(buffers.contacts[contact], buffers.bodies, buffers.centres,
                                    staticIndex, rows);
    startFromKept(buffers.kept[contact], m);
    return m;
}

} // namespace

void buildSoftManifolds(const CoupledIsland& island, std::span<BodySlot> slots,
                        const StepContext& context, Real dt, SoftBuffers& buffers)
{
    // narrow phase once a step: every point the bodies can reach within it (12.1)
    findIslandContacts(island, slots, context, dt, true, buffers.contacts);
    // (12.5): last step's impulses, matched by the other side and the points' feature keys
    buffers.kept.resize(buffers.contacts.size());
    parallelFor(buffers.contacts.size(), context.threads, [&](std::size_t k) {
        prefetchKeptImpulses(island, slots, buffers.contacts, k + kLanesPrefetchedAhead);
        buffers.kept[k] = keptImpulsesOf(island, slots, buffers.contacts[k],
                                         context.settings.contactTolerance);
    });
    const std::size_t staticIndex = island.bodies.size();
    orderSoftContacts(buffers.contacts, staticIndex, context.threads, buffers.order);
    buffers.points = 0;
    for (const IslandContact& contact : buffers.contacts) {
        buffers.points += static_cast<std::size_t>(contact.manifold.pointCount);
    }
    // (12.9): a large island's colours a block of manifolds at a time, the same bits, each
    // manifold built where it is packed; the overflow group (or a small island) keeps its own
    buffers.inLanes = buffers.contacts.size() >= kLaneManifolds;
    const std::size_t first = firstUnpackedManifold(buffers);
    buffers.frictions.resize(buffers.contacts.size());
    buffers.manifolds.resize(buffers.contacts.size() - first);
    parallelFor(buffers.manifolds.size(), context.threads, [&](std::size_t i) {
        buffers.manifolds[i] = manifoldOf(buffers, staticIndex, first + i, true);
    });
    if (buffers.inLanes) {
        buffers.lanes.pack(
            [&](std::size_t k) { return manifoldOf(buffers, staticIndex, k, false); },
            buffers.order.colours, buffers.bodies, context.threads);
    }
}

void restartSoftManifolds(SoftBuffers& buffers, int threads)
{
    if (buffers.inLanes) {
        buffers.lanes.restart(buffers.bodies, buffers.frictions, threads);
    }
    const std::size_t first = firstUnpackedManifold(buffers);
    parallelFor(buffers.manifolds.size(), threads, [&](std::size_t i) {
        const auto [staticFriction, kineticFriction] = buffers.frictions[first + i];
        restartSoftManifold(buffers.manifolds[i], buffers.bodies, staticFriction,
                            kineticFriction);
    });
}

std::size_t firstUnpackedManifold(const SoftBuffers& buffers)
{
    const std::vector<std::uint32_t>& offsets = buffers.order.colours.offsets;
    return buffers.inLanes && offsets.size() >= 2 ? offsets[offsets.size() - 2] : 0;
}

void collectSoftResults(SoftBuffers& buffers, int threads)
{
    buffers.results.resize(buffers.contacts.size());
    if (buffers.inLanes) {
        buffers.lanes.results(buffers.results, threads);
    }
    const std::size_t first = firstUnpackedManifold(buffers);
    for (std::size_t i = 0; i < buffers.manifolds.size(); ++i) {
        buffers.results[first + i] = softResultOf(buffers.manifolds[i]);
    }
}

} // namespace tumble
