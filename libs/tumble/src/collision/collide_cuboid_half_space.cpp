// Cuboid against a half-space of any orientation: a pure function of the pose.
#include "collision/collide_cuboid_half_space.hpp"

#include <algorithm>

#include <glm/geometric.hpp>

namespace tumble {

PairManifold collideCuboidHalfSpace(const Transform& pose, const Vec3& halfExtents,
                                    const Vec3& planePoint, const Vec3& planeNormal, Real margin)
{
    // no vertex lies nearer the plane than the centre less the half diagonal, |R p_i| = |h|:
    // beyond the margin by more than the heights' rounding, none is within it
    const Real radius = glm::length(halfExtents);
    const Real centre = glm::dot(planeNormal, pose.position - planePoint);
    const Real rounding =
        1e-12 * (glm::length(pose.position) + glm::length(planePoint) + radius);
    PairManifold manifold;
    manifold.normal = planeNormal;
    if (centre - radius > margin + rounding) {
        return manifold;
    }
    // (4.1) for a normal n: h_i = n . (x + R p_i - p0); vertices with h_i <= margin, deepest first
    const std::array<Vec3, 8> local = cuboidVertices(halfExtents);
    std::array<std::pair<Real, int>, 8> heights{};
    int count = 0;
    for (int i = 0; i < 8; ++i) {
        const Vec3 vertex = pose.position + pose.orientation * local[i];
        const Real height = glm::dot(planeNormal, vertex - planePoint);
        if (height <= margin) {
            // kept sorted as they come, deepest first (at most eight)
            int at = count++;
            for (; at > 0 && heights[at - 1].first > height; --at) {
                heights[at] = heights[at - 1];
            }
            heights[at] = {height, i};
        }
    }
    // a cuboid has at most four vertices on a face; more within the margin means a face and
    // speculative vertices of the far side, of which the four deepest are the face
    manifold.pointCount = std::min(count, 4);
    for (int k = 0; k < manifold.pointCount; ++k) {
        const auto [height, vertexIndex] = heights[k];
        PairContactPoint& point = manifold.points[k];
        const Vec3 vertex = pose.position + pose.orientation * local[vertexIndex];
        // midway between the vertex and the plane
        point.position = vertex - 0.5 * height * planeNormal;
        point.separation = height;
        point.id = static_cast<std::uint32_t>(vertexIndex);
    }
    return manifold;
}

} // namespace tumble
