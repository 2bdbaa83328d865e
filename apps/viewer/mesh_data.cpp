#include "viewer/mesh_data.hpp"

#include "viewer/palette.hpp"

#include "tumble/shape.hpp"

#include <cmath>
#include <utility>

namespace tumble::viewer {
namespace {

constexpr float kTwoPi = 6.28318531f;

glm::vec3 unitAxis(int axis)
{
    glm::vec3 v(0.0f);
    v[axis] = 1.0f;
    return v;
}

/// Appends a fan closing a circle of radius 1 at height y, facing `normalY` (+1 up, -1 down).
void appendCap(MeshData& mesh, int segments, float y, float normalY)
{
    const auto centre = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.push_back({.position = {0.0f, y, 0.0f}, .normal = {0.0f, normalY, 0.0f}});
    for (int i = 0; i < segments; ++i) {
        const float angle = kTwoPi * static_cast<float>(i) / static_cast<float>(segments);
        mesh.vertices.push_back({.position = {std::cos(angle), y, std::sin(angle)},
                                 .normal = {0.0f, normalY, 0.0f}});
    }
    for (int i = 0; i < segments; ++i) {
        const std::uint32_t a = centre + 1 + static_cast<std::uint32_t>(i);
        const std::uint32_t b = centre + 1 + static_cast<std::uint32_t>((i + 1) % segments);
        // the ring runs from +x towards +z: clockwise seen from above
        if (normalY > 0.0f) {
            mesh.indices.insert(mesh.indices.end(), {centre, b, a});
        } else {
            mesh.indices.insert(mesh.indices.end(), {centre, a, b});
        }
    }
}

/// Appends the side of a cylinder (topRadius 1) or cone (topRadius 0) from y = 0 to y = 1.
void appendSide(MeshData& mesh, int segments, float topRadius)
{
    const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
    // the side's normal leans up by the slope of the side
    const float slope = 1.0f - topRadius;
    for (int i = 0; i <= segments; ++i) {
        const float angle = kTwoPi * static_cast<float>(i) / static_cast<float>(segments);
        const glm::vec3 radial(std::cos(angle), 0.0f, std::sin(angle));
        const glm::vec3 normal = glm::normalize(radial + glm::vec3(0.0f, slope, 0.0f));
        mesh.vertices.push_back({.position = radial, .normal = normal});
        mesh.vertices.push_back({.position = topRadius * radial + glm::vec3(0.0f, 1.0f, 0.0f),
                                 .normal = normal});
    }
    for (int i = 0; i < segments; ++i) {
        const std::uint32_t bottom = first + 2 * static_cast<std::uint32_t>(i);
        const std::uint32_t top = bottom + 1;
        const std::uint32_t nextBottom = bottom + 2;
        const std::uint32_t nextTop = bottom + 3;
        if (topRadius > 0.0f) {
            mesh.indices.insert(mesh.indices.end(),
                                {bottom, top, nextTop, bottom, nextTop, nextBottom});
        } else {
            // a cone's top edge is its apex: one triangle per segment
            mesh.indices.insert(mesh.indices.end(), {bottom, top, nextBottom});
        }
    }
}

} // namespace

MeshData cuboidMesh()
{
    MeshData mesh;
    // faces +x, -x, +y, -y, +z, -z; u x v = n keeps each face counter-clockwise from outside
    for (int face = 0; face < 6; ++face) {
        const int axis = face / 2;
        const float sign = face % 2 == 0 ? 1.0f : -1.0f;
        const glm::vec3 normal = sign * unitAxis(axis);
        glm::vec3 u = unitAxis((axis + 1) % 3);
        glm::vec3 v = unitAxis((axis + 2) % 3);
        if (sign < 0.0f) {
            std::swap(u, v);
        }
        const glm::vec3 colour = palette::faceColour(static_cast<CuboidFace>(face));
        const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
        const glm::vec2 corners[4] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {0.0f, 1.0f}};
        for (const glm::vec2& corner : corners) {
            const glm::vec3 position =
                0.5f * normal + (corner.x - 0.5f) * u + (corner.y - 0.5f) * v;
            mesh.vertices.push_back(
                {.position = position, .normal = normal, .colour = colour, .faceUv = corner});
        }
        mesh.indices.insert(mesh.indices.end(),
                            {first, first + 1, first + 2, first, first + 2, first + 3});
    }
    return mesh;
}

MeshData cylinderMesh(int segments)
{
    MeshData mesh;
    appendSide(mesh, segments, 1.0f);
    appendCap(mesh, segments, 0.0f, -1.0f);
    appendCap(mesh, segments, 1.0f, 1.0f);
    return mesh;
}

MeshData coneMesh(int segments)
{
    MeshData mesh;
    appendSide(mesh, segments, 0.0f);
    appendCap(mesh, segments, 0.0f, -1.0f);
    return mesh;
}

} // namespace tumble::viewer
