// The box-box narrow phase's memory of a body's pairs (docs/physics/09-box-box.md, (9.11)).
#include "collision/pair_geometry_cache.hpp"

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
                                                      const Vec3& halfExtentsB, Real margin)
{
    auto entry = std::find_if(m_entries.begin(), m_entries.end(),
                              [&](const Entry& e) { return e.other == other; });
    if (entry == m_entries.end()) {
        entry = m_entries.insert(m_entries.end(), Entry{});
        entry->other = other;
    } else if (entry->halfExtentsA == halfExtentsA && entry->halfExtentsB == halfExtentsB &&
               withinPairCacheReach(poseA, entry->poseA) &&
               withinPairCacheReach(poseB, entry->poseB) &&
               decidesMargin(entry->geometry, margin)) {
        entry->asked = true;
        return entry->geometry;
    }
    entry->asked = true;
    entry->poseA = poseA;
    entry->poseB = poseB;
    entry->halfExtentsA = halfExtentsA;
    entry->halfExtentsB = halfExtentsB;
    entry->geometry = findCuboidPairGeometry(cuboidFrame(poseA, halfExtentsA),
                                             cuboidFrame(poseB, halfExtentsB), margin);
    return entry->geometry;
}

void PairGeometryCache::forgetUnasked()
{
    std::erase_if(m_entries, [](const Entry& e) { return !e.asked; });
    for (Entry& e : m_entries) {
        e.asked = false;
    }
}

} // namespace tumble
