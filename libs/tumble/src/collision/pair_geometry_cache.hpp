// The box-box narrow phase's memory of a body's pairs: the geometry found at two poses, used
// again while neither body has moved by more than a tiny bound (docs/physics/09-box-box.md,
// (9.11)).
#pragma once

#include "collision/collide_cuboid_cuboid.hpp"
#include "prefetch.hpp"
#include "tumble/math.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace tumble {

/// (9.11): a pair's kept geometry stands while each body is within this distance (m) and this
/// rotation angle (rad) of the pose it was found at. Points of a unit box then lie within about
/// 4e-9 m of where a fresh search would put them, 1e-5 of the default contact tolerance.
inline constexpr Real kPairCacheDistance = 1e-9;
inline constexpr Real kPairCacheAngle = 1e-9;

/// Whether `pose` is within (9.11) of `kept`. Quaternions of opposite sign count as apart.
bool withinPairCacheReach(const Transform& pose, const Transform& kept);

/// The geometry of the pairs one body keeps, each under the other side's slot index.
class PairGeometryCache {
public:
    /// The geometry of cuboid A (the lower slot) with cuboid B, deciding `margin` (m): the kept one
    /// if both poses are within (9.11) of those it was found at and the sizes are the same; with
    /// `carryInto`, the kept one carried to the poses if B moved relative to A within (9.12),
    /// written to *carryInto (the caller's, read at once: a carried geometry is not kept); else
    /// found now and kept.
    const CuboidPairGeometry& geometry(std::uint32_t other, const Transform& poseA,
                                       const Vec3& halfExtentsA, const Transform& poseB,
                                       const Vec3& halfExtentsB, Real margin,
                                       CuboidPairGeometry* carryInto = nullptr);

    /// (10.4b) The touch test's answer for the pair with `other` while both bodies rest: the one
    /// remembered at exactly these poses, sizes and margin, if no geometry was asked for since.
    /// The pair counts as asked (it is not forgotten). Empty if there is none.
    std::optional<bool> restingTouch(std::uint32_t other, const Transform& poseA,
                                     const Vec3& halfExtentsA, const Transform& poseB,
                                     const Vec3& halfExtentsB, Real margin);
    /// Remembers the touch test's answer just found (through geometry) for the pair with `other`
    /// at these poses and margin.
    void rememberRestingTouch(std::uint32_t other, const Transform& poseA, const Transform& poseB,
                              Real margin, bool touches);

    /// Asks the memory for the look-up table and the first entry's header and first points,
    /// ahead of the body's first request of a step (its pairs come in the same order each step).
    void prefetch() const
    {
        if (m_others.empty()) {
            return;
        }
        prefetchLines(m_others.data(), sizeof(std::uint32_t));
        prefetchLines(m_entries.data(), kPrefetchedEntryBytes);
    }

    /// Drops the pairs not asked for since the last call.
    void forgetUnasked();

    void clear()
    {
        m_others.clear();
        m_entries.clear();
    }
    [[nodiscard]] std::size_t size() const { return m_entries.size(); }

private:
    static constexpr std::size_t kPrefetchedEntryBytes = 512;
    /// The fields every request reads come first, then the geometry: a request touches the
    /// entry's header and the points it has (a soft world carries them every step).
    struct Entry {
        bool asked = false;
        Transform poseA{};
        Transform poseB{};
        Vec3 halfExtentsA{0.0};
        Vec3 halfExtentsB{0.0};
        CuboidPairGeometry geometry{};
        /// (10.4b) The touch test's answer at these poses and margin, valid while `restingKnown`
        /// (cleared by every request for the geometry).
        bool restingKnown = false;
        bool restingTouches = false;
        Real restingMargin = 0.0;
        Transform restingPoseA{};
        Transform restingPoseB{};
    };
    /// The entry kept for `other`, or m_entries.size().
    [[nodiscard]] std::size_t indexOf(std::uint32_t other) const;
    /// The other side of each entry, apart from the entries so that finding one reads little.
    std::vector<std::uint32_t> m_others;
    std::vector<Entry> m_entries;
};

} // namespace tumble
