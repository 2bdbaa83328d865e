// The meshes the renderer draws, as plain vertex and index arrays: a unit cuboid with a colour
// and face coordinates per face (for its edges), and the shaft and head of an arrow.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace tumble::viewer {

struct MeshVertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};
    glm::vec3 colour{1.0f};
    /// Coordinates across the face, 0 to 1 from edge to edge (the shader draws edges there).
    glm::vec2 faceUv{0.5f};
};

struct MeshData {
    std::vector<MeshVertex> vertices;
    /// Triangles, counter-clockwise seen from outside.
    std::vector<std::uint32_t> indices;
};

/// The cube [-0.5, 0.5]^3: four vertices per face, faces in CuboidFace order, each with its
/// palette colour.
MeshData cuboidMesh();
/// A closed cylinder of radius 1 from y = 0 to y = 1, white.
MeshData cylinderMesh(int segments);
/// A closed cone with its base of radius 1 at y = 0 and its apex at y = 1, white.
MeshData coneMesh(int segments);

} // namespace tumble::viewer
