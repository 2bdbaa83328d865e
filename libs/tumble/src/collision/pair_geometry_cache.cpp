// The box-box narrow phase's memory of a body's pairs (docs/physics/09-box-box.md, (9.11)).
#include "collision/pair_geometry_cache.hpp"

#include "collision/carried_pair_geometry.hpp"

#include <algorithm>

namespace tumble {

bool withinPairCacheReach(const Transform& pose, const Transform& kept)
{
    // |q - q0| = 2 sin(theta / 4) for unit quaternions of one sign, about half the angle theta
    // between the orientations
    const Real halfAngle = 0.5 * kPairCacheAngle;
    const Quat turn = pose.orientation - kept.orientation;
    return lengthSquared(pose.position - kept.position) <=
               kPairCacheDistance * kPairCacheDistance &&
           turn.w * turn.w + turn.x * turn.x + turn.y * turn.y + turn.z * turn.z <=
               halfAngle * halfAngle;
}

const CuboidPairGeometry& PairGeometryCache::geometry(std::uint32_t other, const Transform& poseA,
                                                      const Vec3& halfExtentsA,
                                                      const Transform& poseB,
                                                      const Vec3& halfExtentsB, Real margin,
                                                      CuboidPairGeometry* carryInto)
{
    const std::size_t index = indexOf(other);
    const bool known = index < m_others.size();
    if (!known) {
        m_others.push_back(other);
        m_entries.emplace_back();
    }
    Entry& entry = m_entries[index];
    entry.asked = true;
    entry.restingKnown = false;
    // the body's pairs come in the same order each step: the next one's entry is asked for
    if (index + 1 < m_entries.size()) {
        prefetchLines(&m_entries[index + 1], sizeof(Entry));
    }
    const bool sameSizes =
        known && entry.halfExtentsA == halfExtentsA && entry.halfExtentsB == halfExtentsB;
    if (sameSizes && withinPairCacheReach(poseA, entry.poseA) &&
        withinPairCacheReach(poseB, entry.poseB) && decidesMargin(entry.geometry, margin)) {
        return entry.geometry;
    }
    if (sameSizes && carryInto != nullptr) {
        const Real move = relativeMove(entry.poseA, entry.poseB, poseA, poseB, halfExtentsB);
        if (move <= carryReach(halfExtentsA, halfExtentsB)) {
            carryPairGeometry(entry.geometry, entry.poseA, entry.poseB, poseA, poseB, move,
                              *carryInto);
            if (decidesMargin(*carryInto, margin)) {
                return *carryInto;
            }
        }
    }
    entry.poseA = poseA;
    entry.poseB = poseB;
    entry.halfExtentsA = halfExtentsA;
    entry.halfExtentsB = halfExtentsB;
    entry.geometry = findCuboidPairGeometry(cuboidFrame(poseA, halfExtentsA),
                                             cuboidFrame(poseB, halfExtentsB), margin);
    return entry.geometry;
}

std::size_t PairGeometryCache::indexOf(std::uint32_t other) const
{
    return static_cast<std::size_t>(std::find(m_others.begin(), m_others.end(), other) -
                                    m_others.begin());
}

namespace {

bool samePose(const Transform& pose, const Transform& kept)
{
    return pose.position == kept.position && pose.orientation == kept.orientation;
}

} // namespace

std::optional<bool> PairGeometryCache::restingTouch(std::uint32_t other, const Transform& poseA,
                                                    const Vec3& halfExtentsA,
                                                    const Transform& poseB,
                                                    const Vec3& halfExtentsB, Real margin)
{
    const std::size_t index = indexOf(other);
    if (index == m_entries.size()) {
        return std::nullopt;
    }
    Entry& entry = m_entries[index];
    entry.asked = true;
    // the geometry asked for again at the same poses, sizes and margin would give the same
    // answer: the entry is left as the request that found it left it (kept or carried,
    // (9.11)-(9.12)), and its sizes are those of that request
    if (!entry.restingKnown || entry.restingMargin != margin ||
        !samePose(poseA, entry.restingPoseA) || !samePose(poseB, entry.restingPoseB) ||
        entry.halfExtentsA != halfExtentsA || entry.halfExtentsB != halfExtentsB) {
        return std::nullopt;
    }
    return entry.restingTouches;
}

void PairGeometryCache::rememberRestingTouch(std::uint32_t other, const Transform& poseA,
                                             const Transform& poseB, Real margin, bool touches)
{
    const std::size_t index = indexOf(other);
    if (index == m_entries.size()) {
        return;
    }
    Entry& entry = m_entries[index];
    entry.restingKnown = true;
    entry.restingTouches = touches;
    entry.restingMargin = margin;
    entry.restingPoseA = poseA;
    entry.restingPoseB = poseB;
}

void PairGeometryCache::forgetUnasked()
{
    std::size_t kept = 0;
    for (std::size_t e = 0; e < m_entries.size(); ++e) {
        if (!m_entries[e].asked) {
            continue;
        }
        if (kept != e) {
            m_others[kept] = m_others[e];
            m_entries[kept] = m_entries[e];
        }
        m_entries[kept++].asked = false;
    }
    m_others.resize(kept);
    m_entries.resize(kept);
}

} // namespace tumble
