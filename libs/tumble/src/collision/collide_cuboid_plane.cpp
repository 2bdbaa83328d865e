// Cuboid-plane detection: a pure function of the pose, testable alone.
#include "collision/collide_cuboid_plane.hpp"

#include <algorithm>

namespace tumble {

std::array<Real, 8> vertexHeights(const Transform& pose, const Vec3& halfExtents, const Plane& plane)
{
    // (4.1): h_i = n . (x + R p_i) - height. With n = +y only the second row of R matters:
    // n . R p_i = sum_k (+-e_k) R_yk, with R_yk from the quaternion (w, x, y, z) (the time of
    // impact evaluates this at every advance, so not eight full rotations).
    const Quat& q = pose.orientation;
    const Real alongX = halfExtents.x * 2.0 * (q.x * q.y + q.w * q.z);
    const Real alongY = halfExtents.y * (1.0 - 2.0 * (q.x * q.x + q.z * q.z));
    const Real alongZ = halfExtents.z * 2.0 * (q.y * q.z - q.w * q.x);
    const Real centre = pose.position.y - plane.height;
    std::array<Real, 8> heights{};
    for (int i = 0; i < 8; ++i) {
        // Vertex i has +e_k where bit k of i is set (cuboidVertices).
        heights[i] = centre + (((i & 1) ? alongX : -alongX) + ((i & 2) ? alongY : -alongY) +
                               ((i & 4) ? alongZ : -alongZ));
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
