// A soft island's manifolds kept while its bodies stay put (12.5b).
#include "step/soft_kept_island.hpp"

#include "step/soft_island_manifolds.hpp"

#include "body_slot.hpp"
#include "parallel_for.hpp"
#include "step/coupled_step.hpp"
#include "step/soft_buffers.hpp"
#include "step/soft_island_manifolds.hpp"
#include "step/soft_warm_start.hpp"

#include <algorithm>
#include <cmath>

namespace tumble {

SoftKeptIsland::SoftKeptIsland() = default;
SoftKeptIsland::~SoftKeptIsland() = default;
SoftKeptIsland::SoftKeptIsland(SoftKeptIsland&& other) noexcept = default;
SoftKeptIsland& SoftKeptIsland::operator=(SoftKeptIsland&& other) noexcept = default;

SoftKeptIsland::SoftKeptIsland(const SoftKeptIsland& other)
    : valid(other.valid), unstored(other.unstored), edits(other.edits), bodies(other.bodies), pairs(other.pairs),
      buffers(other.buffers ? std::make_unique<SoftBuffers>(*other.buffers) : nullptr)
{
}

SoftKeptIsland& SoftKeptIsland::operator=(const SoftKeptIsland& other)
{
    if (this != &other) {
        *this = SoftKeptIsland(other);
    }
    return *this;
}

void SoftKeptIsland::release()
{
    if (valid || buffers != nullptr || bodies.capacity() != 0) {
        *this = SoftKeptIsland{};
    }
}

namespace {

/// Whether a body is within (12.5b) of the pose its manifolds were built at: |c - c0| within
/// the share of its smallest half-extent, and the angle between q and q0, 2 acos |q . q0|, within
/// kSoftKeptAngle (|q . q0| >= cos(kSoftKeptAngle / 2)).
bool stillAt(const Body& body, const Vec3& centre, const Quat& orientation)
{
    const Vec3 half = body.shape.halfExtents();
    const Real reach = kSoftKeptShare * std::min({half.x, half.y, half.z});
    const Real cosine = std::cos(0.5 * kSoftKeptAngle);
    return lengthSquared(body.position - centre) <= reach * reach &&
           std::abs(glm::dot(body.orientation, orientation)) >= cosine;
}

} // namespace

bool softKeptFor(const SoftKeptIsland& kept, const CoupledIsland& island, std::uint64_t edits)
{
    return kept.valid && kept.edits == edits && kept.bodies == island.bodies &&
           kept.pairs == island.pairs;
}

bool softBodiesStill(const SoftBuffers& built, std::span<const std::uint32_t> bodies,
                     std::span<const BodySlot> slots, int threads)
{
    return !parallelAnyOf(bodies.size(), threads, [&](std::size_t i) {
        return !stillAt(slots[bodies[i]].body, built.centres[i], built.startOrientations[i]);
    });
}

void storeKeptSoftIsland(SoftKeptIsland& kept, std::span<BodySlot> slots, int threads)
{
    if (!kept.unstored) {
        return;
    }
    CoupledIsland island;
    island.bodies = kept.bodies;
    // the kept steps leave their impulses in the lanes (SoftStep::gatherWork reads only the work)
    SoftBuffers& built = *kept.buffers;
    collectSoftResults(built, threads);
    storeSoftWarmStart(island, slots, built.contacts, built.results, built.order.colourPosition,
                       threads, built.order.colours.halfSplit, built.centres,
                       built.startOrientations);
    kept.unstored = false;
}

void keepSoftIsland(SoftKeptIsland& kept, const CoupledIsland& island, std::uint64_t edits,
                    std::unique_ptr<SoftBuffers>& built)
{
    kept.valid = true;
    kept.unstored = false;
    kept.edits = edits;
    kept.bodies = island.bodies;
    kept.pairs = island.pairs;
    std::swap(kept.buffers, built);
    if (built == nullptr) {
        built = std::make_unique<SoftBuffers>();
    }
}

} // namespace tumble
