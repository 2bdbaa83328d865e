// Renderer: draws a SceneDrawList seen by an OrbitCamera into the bound framebuffer: sky, the
// ground grid with each cuboid's soft shadow, the cuboids with coloured faces and dark edges,
// arrows and contact markers. It draws only what the draw list holds; it knows nothing of the
// simulation.
#pragma once

#include "viewer/camera.hpp"
#include "viewer/renderer/gl_object.hpp"
#include "viewer/renderer/gpu_mesh.hpp"
#include "viewer/renderer/shader_program.hpp"
#include "viewer/scene_builder.hpp"

#include <glm/glm.hpp>

namespace tumble::viewer {

class Renderer {
public:
    /// Direction towards the light: a sun high up and to the left of the default view, so that
    /// shadows fall to the right, in sight, and the two sides in view are shaded differently.
    static constexpr glm::vec3 kTowardsLight{-0.45f, 1.0f, 0.55f};
    /// Half width of a shadow's soft edge on the ground, m, and how much it widens per metre
    /// the body is above the ground.
    static constexpr float kShadowSoftness = 0.06f;
    static constexpr float kShadowSoftnessPerMetre = 0.08f;
    /// How much of the light a shadow takes away, for a body on the ground.
    static constexpr float kShadowStrength = 0.5f;
    /// Width of the cuboids' edges, pixels.
    static constexpr float kEdgeWidth = 1.6f;
    /// Half the side of the ground grid square, m (it fades out well before its border).
    static constexpr float kGridHalfSize = 400.0f;

    /// Needs a current OpenGL 3.3 core context; throws std::runtime_error if a shader fails.
    Renderer();

    /// Clears the bound framebuffer (framebufferSize pixels) to the window background and draws
    /// `scene` into `viewport`, framebuffer pixels from the top-left corner.
    void draw(const SceneDrawList& scene, const OrbitCamera& camera, const ViewRegion& viewport,
              const glm::ivec2& framebufferSize, bool shadows);

private:
    void drawSky(const glm::mat4& viewProjection);
    void drawGround(const SceneDrawList& scene, const OrbitCamera& camera,
                    const glm::mat4& viewProjection);
    void drawShadows(const SceneDrawList& scene, const glm::mat4& viewProjection);
    void drawCuboids(const SceneDrawList& scene, const glm::mat4& viewProjection,
                     const glm::vec3& eye);
    /// The arrows with this `onTop`.
    void drawArrows(const SceneDrawList& scene, const glm::mat4& viewProjection,
                    const glm::vec3& eye, bool onTop);
    void drawMarkers(const SceneDrawList& scene, const glm::mat4& viewProjection);

    ShaderProgram m_litProgram;
    ShaderProgram m_groundProgram;
    ShaderProgram m_shadowProgram;
    ShaderProgram m_markerProgram;
    ShaderProgram m_skyProgram;
    GpuMesh m_cuboid;
    GpuMesh m_shaft;
    GpuMesh m_head;
    /// An empty vertex array, for the quads drawn from gl_VertexID alone.
    GlObject m_emptyVertexArray;
    GlObject m_markerVertexArray;
    GlObject m_markerBuffer;
};

} // namespace tumble::viewer
