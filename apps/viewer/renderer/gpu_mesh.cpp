#include "viewer/renderer/gpu_mesh.hpp"

#include <cstddef>

namespace tumble::viewer {
namespace {

void floatAttribute(GLuint index, int components, std::size_t offset)
{
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, components, GL_FLOAT, GL_FALSE, sizeof(MeshVertex),
                          reinterpret_cast<const void*>(offset));
}

} // namespace

GpuMesh::GpuMesh(const MeshData& mesh)
    : m_vertexArray(GlObject::create(GlKind::VertexArray)),
      m_vertexBuffer(GlObject::create(GlKind::Buffer)),
      m_indexBuffer(GlObject::create(GlKind::Buffer)),
      m_indexCount(static_cast<GLsizei>(mesh.indices.size()))
{
    glBindVertexArray(m_vertexArray.name());
    glBindBuffer(GL_ARRAY_BUFFER, m_vertexBuffer.name());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(MeshVertex)),
                 mesh.vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_indexBuffer.name());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
                 mesh.indices.data(), GL_STATIC_DRAW);
    floatAttribute(0, 3, offsetof(MeshVertex, position));
    floatAttribute(1, 3, offsetof(MeshVertex, normal));
    floatAttribute(2, 3, offsetof(MeshVertex, colour));
    floatAttribute(3, 2, offsetof(MeshVertex, faceUv));
    glBindVertexArray(0);
}

void GpuMesh::draw() const
{
    glBindVertexArray(m_vertexArray.name());
    glDrawElements(GL_TRIANGLES, m_indexCount, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

} // namespace tumble::viewer
