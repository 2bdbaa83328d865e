// A soft island's manifolds, colours and packed lanes kept from one step to the next while its
// bodies stay near the poses they were built at (docs/physics/12-soft-step.md, (12.5b)).
#pragma once

#include "tumble/math.hpp"

#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace tumble {

struct BodySlot;
struct CoupledIsland;
struct SoftBuffers;

/// (12.5b): a body's kept manifolds stand while its centre stays within this share of its
/// smallest half-extent of where they were built, and its orientation within this angle (rad).
inline constexpr Real kSoftKeptShare = 1e-3;
inline constexpr Real kSoftKeptAngle = 1e-3;

/// The soft step's buffers of the island whose lowest body keeps them, from its last step, with
/// what they were built from: the island's bodies and pairs, and the world's edits then.
struct SoftKeptIsland {
    SoftKeptIsland();
    ~SoftKeptIsland();
    SoftKeptIsland(const SoftKeptIsland& other);
    SoftKeptIsland& operator=(const SoftKeptIsland& other);
    SoftKeptIsland(SoftKeptIsland&& other) noexcept;
    SoftKeptIsland& operator=(SoftKeptIsland&& other) noexcept;

    bool valid = false;
    /// Whether the impulses of the last step are in `buffers` only, not yet in the owners'
    /// caches (a kept step leaves them there, storeKeptSoftIsland puts them in the caches).
    bool unstored = false;
    std::uint64_t edits = 0;
    std::vector<std::uint32_t> bodies;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    /// The buffers of the step that built the manifolds: their `centres`, `startOrientations`
    /// and `startRotationsT` are the poses the manifolds are anchored at.
    std::unique_ptr<SoftBuffers> buffers;

    /// Gives back the memory of an island no step keeps any more.
    void release();
};

/// Whether `kept` holds manifolds built for this island: the same bodies and pairs, and no
/// edit of the world since (`edits` now). Whether its bodies stayed put is softBodiesStill.
bool softKeptFor(const SoftKeptIsland& kept, const CoupledIsland& island, std::uint64_t edits);

/// Whether every one of `bodies` (slot indices, in the order of the island the buffers were
/// built for) is within (12.5b) of its pose in `built` (the poses its manifolds were built at).
bool softBodiesStill(const SoftBuffers& built, std::span<const std::uint32_t> bodies,
                     std::span<const BodySlot> slots, int threads);

/// Puts the impulses `kept` holds unstored into its bodies' caches (storeSoftWarmStart), for
/// the step that builds their manifolds next; writes only the slots of `kept.bodies`.
void storeKeptSoftIsland(SoftKeptIsland& kept, std::span<BodySlot> slots, int threads);

/// Keeps the buffers of a step that built its manifolds now (the island's pairs must come
/// sorted, as the broad phase gives them: they are searched): `built` goes into `kept`, and
/// gives back what `kept` held for the next island to fill.
void keepSoftIsland(SoftKeptIsland& kept, const CoupledIsland& island, std::uint64_t edits,
                    std::unique_ptr<SoftBuffers>& built);

} // namespace tumble
