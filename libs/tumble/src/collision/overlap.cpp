// Overlap depths of a cuboid with another cuboid or a half-space: the checks a scene's loader
// makes before the first step.
#include "collision/cuboid_separating_axis.hpp"
#include "tumble/shape.hpp"

#include <algorithm>
#include <limits>

namespace tumble {

Real cuboidOverlapDepth(const Transform& poseA, const Vec3& halfExtentsA, const Transform& poseB,
                        const Vec3& halfExtentsB)
{
    // with an unbounded margin the test always returns its axis of greatest separation (9.4)
    const std::optional<ContactAxis> axis =
        findContactAxis(cuboidFrame(poseA, halfExtentsA), cuboidFrame(poseB, halfExtentsB),
                        std::numeric_limits<Real>::infinity());
    return axis ? -axis->separation : -std::numeric_limits<Real>::infinity();
}

Real cuboidHalfSpaceDepth(const Transform& pose, const Vec3& halfExtents, const StaticPlane& plane)
{
    Real lowest = std::numeric_limits<Real>::infinity();
    for (const Vec3& vertex : cuboidVertices(halfExtents)) {
        lowest = std::min(lowest,
                          glm::dot(plane.normal, pose.position + pose.orientation * vertex -
                                                     plane.point));
    }
    return -lowest;
}

} // namespace tumble
