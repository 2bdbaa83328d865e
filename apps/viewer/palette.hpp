// The viewer's colours: one per cuboid face (so rotation reads at a glance), the markers and
// arrows, and the background. Shared by the renderer and the panels' swatches.
#pragma once

#include "tumble/shape.hpp"

#include <glm/glm.hpp>

namespace tumble::viewer::palette {

/// Face colours, saturated so that they stand apart from the grey ground and sky.
inline glm::vec3 faceColour(CuboidFace face)
{
    switch (face) {
    case CuboidFace::PlusX:
        return {0.88f, 0.24f, 0.20f}; // red
    case CuboidFace::MinusX:
        return {0.16f, 0.66f, 0.82f}; // teal
    case CuboidFace::PlusY:
        return {0.95f, 0.78f, 0.16f}; // yellow
    case CuboidFace::MinusY:
        return {0.52f, 0.30f, 0.84f}; // violet
    case CuboidFace::PlusZ:
        return {0.26f, 0.74f, 0.30f}; // green
    case CuboidFace::MinusZ:
        return {0.96f, 0.50f, 0.12f}; // orange
    }
    return {1.0f, 1.0f, 1.0f};
}

/// Around the 3D view: the panels' background (ImGui's dark window colour).
inline constexpr glm::vec3 kBackground{0.06f, 0.06f, 0.06f};
inline constexpr glm::vec3 kEdge{0.08f, 0.08f, 0.10f};
/// Static geometry (walls, trays, plane patches): the face colours dimmed towards grey.
inline constexpr glm::vec3 kStaticTint{0.45f, 0.45f, 0.47f};
inline constexpr glm::vec3 kSelectedEdge{0.98f, 0.98f, 0.98f};
inline constexpr glm::vec3 kSkyTop{0.40f, 0.45f, 0.52f};
inline constexpr glm::vec3 kSkyHorizon{0.78f, 0.80f, 0.83f};
inline constexpr glm::vec3 kGround{0.74f, 0.75f, 0.76f};
inline constexpr glm::vec3 kGridMinor{0.62f, 0.63f, 0.65f};
inline constexpr glm::vec3 kGridMajor{0.46f, 0.47f, 0.50f};
inline constexpr glm::vec3 kContactVertex{1.0f, 0.15f, 0.15f};
inline constexpr glm::vec3 kContactAverage{1.0f, 0.92f, 0.10f};
inline constexpr glm::vec3 kNormalImpulse{0.98f, 0.86f, 0.18f};
inline constexpr glm::vec3 kFrictionImpulse{0.95f, 0.35f, 0.10f};
inline constexpr glm::vec3 kAngularVelocity{0.86f, 0.22f, 0.86f};
inline constexpr glm::vec3 kAngularMomentum{0.10f, 0.80f, 0.85f};
inline constexpr glm::vec3 kAxisX{0.90f, 0.20f, 0.20f};
inline constexpr glm::vec3 kAxisY{0.20f, 0.78f, 0.22f};
inline constexpr glm::vec3 kAxisZ{0.22f, 0.40f, 0.95f};

} // namespace tumble::viewer::palette
