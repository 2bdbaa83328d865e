// Faces and edges of a posed cuboid (docs/physics/09-box-box.md).
#include "collision/cuboid_features.hpp"

namespace tumble {

CuboidFrame cuboidFrame(const Transform& pose, const Vec3& halfExtents)
{
    const Mat3 rotation = glm::mat3_cast(pose.orientation);
    return CuboidFrame{pose.position, {rotation[0], rotation[1], rotation[2]}, halfExtents};
}

Vec3 faceNormal(const CuboidFrame& box, int face)
{
    return faceSign(face) * box.axes[faceAxis(face)];
}

std::array<Vec3, 4> faceCorners(const CuboidFrame& box, int face)
{
    const int axis = faceAxis(face);
    const int j1 = (axis + 1) % 3;
    const int j2 = (axis + 2) % 3;
    const Vec3 centre = box.centre + faceSign(face) * box.halfExtents[axis] * box.axes[axis];
    const Vec3 u = box.halfExtents[j1] * box.axes[j1];
    const Vec3 v = box.halfExtents[j2] * box.axes[j2];
    return {centre - u - v, centre + u - v, centre + u + v, centre - u + v};
}

CuboidEdge supportEdge(const CuboidFrame& box, int axis, const Vec3& direction)
{
    const int j1 = (axis + 1) % 3;
    const int j2 = (axis + 2) % 3;
    const bool plus1 = glm::dot(box.axes[j1], direction) >= 0.0;
    const bool plus2 = glm::dot(box.axes[j2], direction) >= 0.0;
    CuboidEdge edge;
    edge.midpoint = box.centre +
                    (plus1 ? 1.0 : -1.0) * box.halfExtents[j1] * box.axes[j1] +
                    (plus2 ? 1.0 : -1.0) * box.halfExtents[j2] * box.axes[j2];
    edge.direction = box.axes[axis];
    edge.halfLength = box.halfExtents[axis];
    edge.index = 4 * axis + (plus1 ? 1 : 0) + (plus2 ? 2 : 0);
    return edge;
}

} // namespace tumble
