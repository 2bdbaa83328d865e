// GLSL 330 sources of the viewer's shaders: lit meshes (cuboids with edges, arrows), the ground
// grid, the soft ground shadow, contact markers and the sky.
#pragma once

namespace tumble::viewer::shaders {

inline constexpr const char* kLitVertex = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColour;
layout(location = 3) in vec2 aFaceUv;
uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform mat4 uViewProjection;
out vec3 vWorldPosition;
out vec3 vNormal;
out vec3 vColour;
out vec2 vFaceUv;
void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorldPosition = world.xyz;
    vNormal = uNormalMatrix * aNormal;
    vColour = aColour;
    vFaceUv = aFaceUv;
    gl_Position = uViewProjection * world;
}
)";

inline constexpr const char* kLitFragment = R"(#version 330 core
in vec3 vWorldPosition;
in vec3 vNormal;
in vec3 vColour;
in vec2 vFaceUv;
uniform vec3 uLightDirection;
uniform vec3 uCameraPosition;
uniform vec3 uTint;
uniform float uEdgeWidth;
uniform vec3 uEdgeColour;
out vec4 fragColour;
void main() {
    vec3 n = normalize(vNormal);
    vec3 base = vColour * uTint;
    // hemisphere ambient, Lambert diffuse, a faint Blinn-Phong highlight
    float diffuse = max(dot(n, uLightDirection), 0.0);
    vec3 colour = base * (0.34 + 0.10 * n.y + 0.62 * diffuse);
    vec3 toEye = normalize(uCameraPosition - vWorldPosition);
    vec3 halfway = normalize(toEye + uLightDirection);
    colour += vec3(0.10) * pow(max(dot(n, halfway), 0.0), 40.0);
    // edges: a band uEdgeWidth pixels wide along the face's border
    if (uEdgeWidth > 0.0) {
        vec2 toBorder = min(vFaceUv, 1.0 - vFaceUv);
        vec2 perPixel = fwidth(vFaceUv);
        vec2 inside = smoothstep(perPixel * (uEdgeWidth - 1.0), perPixel * uEdgeWidth, toBorder);
        colour = mix(uEdgeColour, colour, min(inside.x, inside.y));
    }
    fragColour = vec4(colour, 1.0);
}
)";

inline constexpr const char* kGroundVertex = R"(#version 330 core
uniform vec2 uGridCentre;
uniform float uGridHalfSize;
uniform float uGridHeight;
uniform mat4 uViewProjection;
out vec3 vWorldPosition;
void main() {
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1) * 2.0 - 1.0;
    vec3 world = vec3(uGridCentre.x + corner.x * uGridHalfSize, uGridHeight,
                      uGridCentre.y + corner.y * uGridHalfSize);
    vWorldPosition = world;
    gl_Position = uViewProjection * vec4(world, 1.0);
}
)";

inline constexpr const char* kGroundFragment = R"(#version 330 core
in vec3 vWorldPosition;
uniform vec3 uCameraPosition;
uniform vec3 uGroundColour;
uniform vec3 uMinorColour;
uniform vec3 uMajorColour;
uniform vec3 uFogColour;
uniform float uFogStart;
uniform float uFogEnd;
uniform float uOpacity;
out vec4 fragColour;
// 1 on a grid line (at whole grid units), about one pixel wide, 0 between lines; `perPixel` is
// fwidth(coord)
float gridLine(vec2 coord, vec2 perPixel) {
    vec2 distance = abs(fract(coord - 0.5) - 0.5) / perPixel;
    return 1.0 - min(min(distance.x, distance.y), 1.0);
}
void main() {
    // minor lines every metre, major lines every five
    vec2 coord = vWorldPosition.xz;
    vec2 perPixel = fwidth(coord);
    vec3 colour = mix(uGroundColour, uMinorColour, gridLine(coord, perPixel));
    colour = mix(colour, uMajorColour, gridLine(coord * 0.2, perPixel * 0.2));
    float fog = smoothstep(uFogStart, uFogEnd, length(vWorldPosition - uCameraPosition));
    fragColour = vec4(mix(colour, uFogColour, fog), uOpacity * (1.0 - fog));
}
)";

inline constexpr const char* kShadowVertex = R"(#version 330 core
uniform vec2 uLow;
uniform vec2 uHigh;
uniform float uHeight;
uniform mat4 uViewProjection;
out vec2 vGround;
void main() {
    vec2 corner = vec2(gl_VertexID & 1, gl_VertexID >> 1);
    vGround = mix(uLow, uHigh, corner);
    gl_Position = uViewProjection * vec4(vGround.x, uHeight, vGround.y, 1.0);
}
)";

/// Darkens the ground under the shadow polygon (ground x, z), with a soft edge uSoftness wide
/// on either side; drawn with multiplicative blending.
inline constexpr const char* kShadowFragment = R"(#version 330 core
in vec2 vGround;
uniform vec2 uHull[8];
uniform int uHullCount;
uniform float uSoftness;
uniform float uStrength;
out vec4 fragColour;
void main() {
    // distance to the nearest edge, and whether the point is left of every edge
    float outside = 1e9;
    bool inside = true;
    for (int i = 0; i < uHullCount; ++i) {
        vec2 a = uHull[i];
        vec2 edge = uHull[(i + 1) % uHullCount] - a;
        vec2 toPoint = vGround - a;
        float along = clamp(dot(toPoint, edge) / dot(edge, edge), 0.0, 1.0);
        outside = min(outside, length(toPoint - edge * along));
        if (edge.x * toPoint.y - edge.y * toPoint.x < 0.0) inside = false;
    }
    float signedDistance = inside ? -outside : outside;
    float shade = uStrength * (1.0 - smoothstep(-uSoftness, uSoftness, signedDistance));
    fragColour = vec4(vec3(1.0 - shade), 1.0);
}
)";

inline constexpr const char* kMarkerVertex = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aColour;
layout(location = 2) in float aSize;
uniform mat4 uViewProjection;
out vec3 vColour;
void main() {
    vColour = aColour;
    gl_PointSize = aSize;
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
)";

inline constexpr const char* kMarkerFragment = R"(#version 330 core
in vec3 vColour;
out vec4 fragColour;
void main() {
    // a disc with a dark rim
    float radius = length(gl_PointCoord * 2.0 - 1.0);
    if (radius > 1.0) discard;
    fragColour = vec4(radius > 0.68 ? vec3(0.05) : vColour, 1.0);
}
)";

inline constexpr const char* kSkyVertex = R"(#version 330 core
out vec2 vDevice;
void main() {
    // one triangle covering the screen
    vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2) * 2.0 - 1.0;
    vDevice = corner;
    gl_Position = vec4(corner, 1.0, 1.0);
}
)";

inline constexpr const char* kSkyFragment = R"(#version 330 core
in vec2 vDevice;
uniform mat4 uInverseViewProjection;
uniform vec3 uSkyTop;
uniform vec3 uSkyHorizon;
out vec4 fragColour;
void main() {
    // the colour follows the view ray's elevation, so the horizon meets the fogged ground
    vec4 near = uInverseViewProjection * vec4(vDevice, -1.0, 1.0);
    vec4 far = uInverseViewProjection * vec4(vDevice, 1.0, 1.0);
    vec3 ray = normalize(far.xyz / far.w - near.xyz / near.w);
    fragColour = vec4(mix(uSkyHorizon, uSkyTop, smoothstep(0.0, 0.45, ray.y)), 1.0);
}
)";

} // namespace tumble::viewer::shaders
