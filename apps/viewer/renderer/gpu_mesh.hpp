// GpuMesh: a MeshData uploaded to a vertex array (attributes 0 position, 1 normal, 2 colour,
// 3 face coordinates) and drawn as indexed triangles.
#pragma once

#include "viewer/mesh_data.hpp"
#include "viewer/renderer/gl_object.hpp"

namespace tumble::viewer {

class GpuMesh {
public:
    explicit GpuMesh(const MeshData& mesh);

    void draw() const;

private:
    GlObject m_vertexArray;
    GlObject m_vertexBuffer;
    GlObject m_indexBuffer;
    GLsizei m_indexCount = 0;
};

} // namespace tumble::viewer
