#include "viewer/renderer/renderer.hpp"

#include "viewer/ground_shadow.hpp"
#include "viewer/mesh_data.hpp"
#include "viewer/palette.hpp"
#include "viewer/renderer/shaders.hpp"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace tumble::viewer {
namespace {

constexpr int kArrowSegments = 14;
/// Most corners a cuboid's shadow can have (the shader's array size).
constexpr std::size_t kMaxShadowCorners = 8;

/// Lowest height any corner of the cuboid `model` reaches, m.
float lowestCorner(const glm::mat4& model)
{
    float lowest = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec4 local((corner & 1) ? 0.5f : -0.5f, (corner & 2) ? 0.5f : -0.5f,
                              (corner & 4) ? 0.5f : -0.5f, 1.0f);
        const float height = (model * local).y;
        lowest = corner == 0 ? height : std::min(lowest, height);
    }
    return lowest;
}

/// Takes the +y unit mesh to the segment from `from` along `along`, `radius` thick.
glm::mat4 alongSegment(const glm::vec3& from, const glm::vec3& along, float radius)
{
    const float length = glm::length(along);
    const glm::vec3 axis = along / length;
    const glm::vec3 helper =
        std::fabs(axis.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 side = glm::normalize(glm::cross(helper, axis));
    const glm::vec3 other = glm::cross(axis, side);
    glm::mat4 model(1.0f);
    model[0] = glm::vec4(side * radius, 0.0f);
    model[1] = glm::vec4(along, 0.0f);
    model[2] = glm::vec4(other * radius, 0.0f);
    model[3] = glm::vec4(from, 1.0f);
    return model;
}

/// One marker as the marker shader reads it.
struct MarkerVertex {
    glm::vec3 position;
    glm::vec3 colour;
    float size;
};

} // namespace

Renderer::Renderer()
    : m_litProgram("lit", shaders::kLitVertex, shaders::kLitFragment),
      m_groundProgram("ground", shaders::kGroundVertex, shaders::kGroundFragment),
      m_shadowProgram("shadow", shaders::kShadowVertex, shaders::kShadowFragment),
      m_markerProgram("marker", shaders::kMarkerVertex, shaders::kMarkerFragment),
      m_skyProgram("sky", shaders::kSkyVertex, shaders::kSkyFragment), m_cuboid(cuboidMesh()),
      m_shaft(cylinderMesh(kArrowSegments)), m_head(coneMesh(kArrowSegments)),
      m_emptyVertexArray(GlObject::create(GlKind::VertexArray)),
      m_markerVertexArray(GlObject::create(GlKind::VertexArray)),
      m_markerBuffer(GlObject::create(GlKind::Buffer))
{
    // the marker stream: position, colour, size per point
    glBindVertexArray(m_markerVertexArray.name());
    glBindBuffer(GL_ARRAY_BUFFER, m_markerBuffer.name());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(MarkerVertex),
                          reinterpret_cast<const void*>(offsetof(MarkerVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(MarkerVertex),
                          reinterpret_cast<const void*>(offsetof(MarkerVertex, colour)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, sizeof(MarkerVertex),
                          reinterpret_cast<const void*>(offsetof(MarkerVertex, size)));
    glBindVertexArray(0);
}

void Renderer::draw(const SceneDrawList& scene, const OrbitCamera& camera,
                    const ViewRegion& viewport, const glm::ivec2& framebufferSize, bool shadows)
{
    // the whole framebuffer to the window background, then the scene inside its viewport
    glDisable(GL_SCISSOR_TEST);
    glDepthMask(GL_TRUE);
    glClearColor(palette::kBackground.r, palette::kBackground.g, palette::kBackground.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const glm::ivec2 low(glm::round(viewport.min));
    const glm::ivec2 size = glm::max(glm::ivec2(glm::round(viewport.size())), glm::ivec2(1));
    // GL counts rows from the bottom
    glViewport(low.x, framebufferSize.y - low.y - size.y, size.x, size.y);
    glScissor(low.x, framebufferSize.y - low.y - size.y, size.x, size.y);
    glEnable(GL_SCISSOR_TEST);

    const float aspect = static_cast<float>(size.x) / static_cast<float>(size.y);
    const glm::mat4 viewProjection = camera.projection(aspect) * camera.view();
    if (scene.gridIsGround) {
        drawGround(scene, camera, viewProjection);
        if (shadows) {
            drawShadows(scene, viewProjection);
        }
    }
    drawCuboids(scene, viewProjection, camera.eye());
    drawArrows(scene, viewProjection, camera.eye(), false);
    // the sky last of the opaque parts, only where nothing else is (cheaper in software)
    drawSky(viewProjection);
    if (!scene.gridIsGround) {
        // a reference grid is see-through, so it goes after what it may be seen through
        drawGround(scene, camera, viewProjection);
    }
    // the overlays: seen through the bodies
    glClear(GL_DEPTH_BUFFER_BIT);
    drawArrows(scene, viewProjection, camera.eye(), true);
    drawMarkers(scene, viewProjection);
    glDisable(GL_SCISSOR_TEST);
}

void Renderer::drawSky(const glm::mat4& viewProjection)
{
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    m_skyProgram.use();
    m_skyProgram.set("uInverseViewProjection", glm::inverse(viewProjection));
    m_skyProgram.set("uSkyTop", palette::kSkyTop);
    m_skyProgram.set("uSkyHorizon", palette::kSkyHorizon);
    glBindVertexArray(m_emptyVertexArray.name());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDepthMask(GL_TRUE);
}

void Renderer::drawGround(const SceneDrawList& scene, const OrbitCamera& camera,
                          const glm::mat4& viewProjection)
{
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDisable(GL_CULL_FACE);
    // a reference grid blends over the scene and leaves the depth alone
    const bool reference = !scene.gridIsGround;
    if (reference) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
    }
    m_groundProgram.use();
    m_groundProgram.set("uViewProjection", viewProjection);
    m_groundProgram.set("uGridCentre", glm::vec2(camera.target().x, camera.target().z));
    m_groundProgram.set("uGridHalfSize", kGridHalfSize);
    m_groundProgram.set("uGridHeight", scene.gridHeight);
    m_groundProgram.set("uCameraPosition", camera.eye());
    m_groundProgram.set("uGroundColour", palette::kGround);
    m_groundProgram.set("uMinorColour", palette::kGridMinor);
    m_groundProgram.set("uMajorColour", palette::kGridMajor);
    m_groundProgram.set("uFogColour", palette::kSkyHorizon);
    // the grid fades into the horizon beyond a few times the viewing distance
    m_groundProgram.set("uFogStart", 1.5f * camera.distance());
    m_groundProgram.set("uFogEnd", 5.0f * camera.distance() + 20.0f);
    m_groundProgram.set("uOpacity", reference ? 0.45f : 1.0f);
    glBindVertexArray(m_emptyVertexArray.name());
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glBindVertexArray(0);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

void Renderer::drawShadows(const SceneDrawList& scene, const glm::mat4& viewProjection)
{
    // each cuboid darkens the ground under its shadow polygon; the cuboids are drawn after
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_DST_COLOR, GL_ZERO);
    m_shadowProgram.use();
    m_shadowProgram.set("uViewProjection", viewProjection);
    m_shadowProgram.set("uHeight", scene.gridHeight);
    const glm::vec3 towardsLight = glm::normalize(kTowardsLight);
    glBindVertexArray(m_emptyVertexArray.name());
    for (const CuboidInstance& cuboid : scene.cuboids) {
        const std::vector<glm::vec2> hull =
            groundShadow(cuboid.model, towardsLight, scene.gridHeight);
        if (hull.size() < 3 || hull.size() > kMaxShadowCorners) {
            continue;
        }
        // softer and fainter the higher the body is above the ground
        const float gap = std::max(lowestCorner(cuboid.model) - scene.gridHeight, 0.0f);
        const float softness = kShadowSoftness + kShadowSoftnessPerMetre * gap;
        glm::vec2 low = hull[0];
        glm::vec2 high = hull[0];
        for (const glm::vec2& corner : hull) {
            low = glm::min(low, corner);
            high = glm::max(high, corner);
        }
        m_shadowProgram.set("uLow", low - softness);
        m_shadowProgram.set("uHigh", high + softness);
        m_shadowProgram.set("uHull", hull.data(), static_cast<int>(hull.size()));
        m_shadowProgram.set("uHullCount", static_cast<int>(hull.size()));
        m_shadowProgram.set("uSoftness", softness);
        m_shadowProgram.set("uStrength", kShadowStrength / (1.0f + 0.1f * gap));
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    }
    glBindVertexArray(0);
    glDisable(GL_BLEND);
}

void Renderer::drawCuboids(const SceneDrawList& scene, const glm::mat4& viewProjection,
                           const glm::vec3& eye)
{
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    m_litProgram.use();
    m_litProgram.set("uViewProjection", viewProjection);
    m_litProgram.set("uLightDirection", glm::normalize(kTowardsLight));
    m_litProgram.set("uCameraPosition", eye);
    m_litProgram.set("uTint", glm::vec3(1.0f));
    m_litProgram.set("uEdgeWidth", kEdgeWidth);
    for (const CuboidInstance& cuboid : scene.cuboids) {
        m_litProgram.set("uTint", cuboid.fixed ? palette::kStaticTint : glm::vec3(1.0f));
        m_litProgram.set("uEdgeColour", cuboid.selected ? palette::kSelectedEdge : palette::kEdge);
        m_litProgram.set("uModel", cuboid.model);
        m_litProgram.set("uNormalMatrix", cuboid.normalMatrix);
        m_cuboid.draw();
    }
}

void Renderer::drawArrows(const SceneDrawList& scene, const glm::mat4& viewProjection,
                          const glm::vec3& eye, bool onTop)
{
    if (std::none_of(scene.arrows.begin(), scene.arrows.end(),
                     [&](const ArrowInstance& arrow) { return arrow.onTop == onTop; })) {
        return;
    }
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    m_litProgram.use();
    m_litProgram.set("uViewProjection", viewProjection);
    m_litProgram.set("uLightDirection", glm::normalize(kTowardsLight));
    m_litProgram.set("uCameraPosition", eye);
    m_litProgram.set("uEdgeWidth", 0.0f);
    for (const ArrowInstance& arrow : scene.arrows) {
        if (arrow.onTop != onTop) {
            continue;
        }
        // a shaft, then a head of at most a third of the length
        const glm::vec3 along = arrow.to - arrow.from;
        const float length = glm::length(along);
        const float headLength = std::min(0.33f * length, 7.0f * arrow.radius);
        const glm::vec3 direction = along / length;
        const glm::vec3 headStart = arrow.to - direction * headLength;
        m_litProgram.set("uTint", arrow.colour);

        if (length - headLength > kMinArrowLength) {
            const glm::mat4 shaft = alongSegment(arrow.from, headStart - arrow.from, arrow.radius);
            m_litProgram.set("uModel", shaft);
            m_litProgram.set("uNormalMatrix", glm::inverseTranspose(glm::mat3(shaft)));
            m_shaft.draw();
        }
        const glm::mat4 head = alongSegment(headStart, direction * headLength, 2.4f * arrow.radius);
        m_litProgram.set("uModel", head);
        m_litProgram.set("uNormalMatrix", glm::inverseTranspose(glm::mat3(head)));
        m_head.draw();
    }
}

void Renderer::drawMarkers(const SceneDrawList& scene, const glm::mat4& viewProjection)
{
    if (scene.markers.empty()) {
        return;
    }
    std::vector<MarkerVertex> vertices;
    for (const MarkerInstance& marker : scene.markers) {
        vertices.push_back({marker.position, marker.colour, marker.sizePixels});
    }
    // markers stay visible through the body and the ground
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_PROGRAM_POINT_SIZE);
    m_markerProgram.use();
    m_markerProgram.set("uViewProjection", viewProjection);
    glBindVertexArray(m_markerVertexArray.name());
    glBindBuffer(GL_ARRAY_BUFFER, m_markerBuffer.name());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(MarkerVertex)),
                 vertices.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(vertices.size()));
    glBindVertexArray(0);
    glDisable(GL_PROGRAM_POINT_SIZE);
}

} // namespace tumble::viewer
