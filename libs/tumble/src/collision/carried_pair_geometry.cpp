// A pair's box-box geometry carried along with its bodies (docs/physics/09-box-box.md, (9.12)).
#include "collision/carried_pair_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace tumble {

Real relativeMove(const Transform& keptA, const Transform& keptB, const Transform& poseA,
                  const Transform& poseB, const Vec3& halfExtentsB)
{
    // B's centre and orientation in A's frame, then and now
    const Vec3 centreThen =
        glm::conjugate(keptA.orientation) * (keptB.position - keptA.position);
    const Vec3 centreNow = glm::conjugate(poseA.orientation) * (poseB.position - poseA.position);
    const Quat turnThen = glm::conjugate(keptA.orientation) * keptB.orientation;
    const Quat turnNow = glm::conjugate(poseA.orientation) * poseB.orientation;
    // |q - q0| = 2 sin(theta / 4) for unit quaternions of one sign; of opposite signs it is
    // above sqrt(2) and the angle bound below is pi, beyond any reach
    const Quat difference = turnNow - turnThen;
    const Real chord = std::sqrt(difference.w * difference.w + difference.x * difference.x +
                                 difference.y * difference.y + difference.z * difference.z);
    const Real angle = 4.0 * std::asin(std::min(1.0, 0.5 * chord));
    return glm::length(centreNow - centreThen) + angle * glm::length(halfExtentsB);
}

Real carryReach(const Vec3& halfExtentsA, const Vec3& halfExtentsB)
{
    const Real shortest = std::min({halfExtentsA.x, halfExtentsA.y, halfExtentsA.z,
                                    halfExtentsB.x, halfExtentsB.y, halfExtentsB.z});
    return kCarryShare * shortest;
}

void carryPairGeometry(const CuboidPairGeometry& found, const Transform& keptA,
                       const Transform& keptB, const Transform& poseA, const Transform& poseB,
                       Real move, CuboidPairGeometry& carried)
{
    carried.largestSeparation = found.largestSeparation - move;
    carried.complete = found.complete;
    carried.normalOfB = found.normalOfB;
    carried.normal = found.normal;
    carried.points.count = found.complete ? found.points.count : 0;
    if (!found.complete) {
        return;
    }
    // the rotation of each body since the geometry was found, R(q) R(q0)^T
    const Mat3 turnA = glm::mat3_cast(poseA.orientation * glm::conjugate(keptA.orientation));
    const Mat3 turnB = glm::mat3_cast(poseB.orientation * glm::conjugate(keptB.orientation));
    carried.normal = glm::normalize((found.normalOfB ? turnB : turnA) * found.normal);
    for (int k = 0; k < found.points.count; ++k) {
        const PairContactPoint& point = found.points.points[k];
        // the point's ends on A's and on B's surface, each moved with its body
        const Vec3 onA = point.position - 0.5 * point.separation * found.normal;
        const Vec3 onB = point.position + 0.5 * point.separation * found.normal;
        const Vec3 movedA = poseA.position + turnA * (onA - keptA.position);
        const Vec3 movedB = poseB.position + turnB * (onB - keptB.position);
        PairContactPoint& to = carried.points.points[k];
        to.position = 0.5 * (movedA + movedB);
        to.separation = glm::dot(movedB - movedA, carried.normal);
        to.id = point.id;
    }
}

} // namespace tumble
