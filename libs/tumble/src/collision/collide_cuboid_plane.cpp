// Cuboid-plane detection: a pure function of the pose, testable alone.
#include "collision/collide_cuboid_plane.hpp"

#include <algorithm>

namespace tumble {

std::array<Real, 8> vertexHeights(const Transform& pose, const Vec3& halfExtents, const Plane& plane)
{
    // (4.1): h_i = n . (x + R p_i) - height. With n = +y only the second row of R matters.
    const std::array<Vec3, 8> local = cuboidVertices(halfExtents);
    std::array<Real, 8> heights{};
    for (int i = 0; i < 8; ++i) {
        heights[i] = glm::dot(Plane::normal(), pose.position + pose.orientation * local[i]) -
                     plane.height;
    }
    return heights;
}

ContactManifold collideCuboidPlane(const Transform& pose, const Vec3& halfExtents,
                                   const Plane& plane, Real tolerance)
{
    ContactManifold manifold;
    manifold.normal = Plane::normal();
    const std::array<Vec3, 8> local = cuboidVertices(halfExtents);
    const std::array<Real, 8> heights = vertexHeights(pose, halfExtents, plane);
    for (int i = 0; i < 8; ++i) {
        if (heights[i] <= tolerance) {
            ContactPoint& point = manifold.points[manifold.pointCount++];
            point.vertex = i;
            point.position = pose.position + pose.orientation * local[i];
            point.penetration = -heights[i];
        }
    }
    return manifold;
}

Real lowestVertexHeight(const Transform& pose, const Vec3& halfExtents, const Plane& plane)
{
    const std::array<Real, 8> heights = vertexHeights(pose, halfExtents, plane);
    return *std::min_element(heights.begin(), heights.end());
}

} // namespace tumble
