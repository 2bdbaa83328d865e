#include "viewer/mesh_data.hpp"

#include "viewer/palette.hpp"

#include <gtest/gtest.h>

namespace tumble::viewer {
namespace {

/// Every triangle faces away from the mesh's centre (0, 0.5, 0 for the arrow parts).
void expectOutwardTriangles(const MeshData& mesh, const glm::vec3& centre)
{
    ASSERT_EQ(mesh.indices.size() % 3, 0u);
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        const glm::vec3& a = mesh.vertices[mesh.indices[i]].position;
        const glm::vec3& b = mesh.vertices[mesh.indices[i + 1]].position;
        const glm::vec3& c = mesh.vertices[mesh.indices[i + 2]].position;
        const glm::vec3 normal = glm::cross(b - a, c - a);
        EXPECT_GT(glm::dot(normal, (a + b + c) / 3.0f - centre), 0.0f) << "triangle " << i / 3;
    }
}

TEST(CuboidMesh, FourVerticesPerFaceInCuboidFaceOrder)
{
    const MeshData mesh = cuboidMesh();
    ASSERT_EQ(mesh.vertices.size(), 24u);
    EXPECT_EQ(mesh.indices.size(), 36u);
    const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int face = 0; face < 6; ++face) {
        for (int corner = 0; corner < 4; ++corner) {
            const MeshVertex& vertex = mesh.vertices[static_cast<std::size_t>(4 * face + corner)];
            EXPECT_EQ(vertex.normal, normals[face]);
            EXPECT_EQ(vertex.colour, palette::faceColour(static_cast<CuboidFace>(face)));
            EXPECT_FLOAT_EQ(glm::dot(vertex.position, vertex.normal), 0.5f);
        }
    }
    expectOutwardTriangles(mesh, glm::vec3(0.0f));
}

TEST(ArrowMeshes, AreClosedAndFaceOutwards)
{
    expectOutwardTriangles(cylinderMesh(12), glm::vec3(0.0f, 0.5f, 0.0f));
    expectOutwardTriangles(coneMesh(12), glm::vec3(0.0f, 0.25f, 0.0f));
}

} // namespace
} // namespace tumble::viewer
