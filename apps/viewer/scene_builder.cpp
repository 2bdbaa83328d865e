#include "viewer/scene_builder.hpp"

#include "viewer/palette.hpp"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace tumble::viewer {
namespace {

void addArrow(SceneDrawList& list, const glm::vec3& from, const glm::vec3& vector,
              const glm::vec3& colour, float radius, bool onTop = false)
{
    if (glm::length(vector) >= kMinArrowLength) {
        list.arrows.push_back(
            {.from = from, .to = from + vector, .colour = colour, .radius = radius, .onTop = onTop});
    }
}

CuboidInstance cuboidOf(const Body& body, bool selected)
{
    const glm::vec3 position(body.position);
    const glm::vec3 size(body.shape.size);
    const glm::mat4 rotation = glm::mat4_cast(glm::quat(body.orientation));
    const glm::mat4 model =
        glm::scale(glm::translate(glm::mat4(1.0f), position) * rotation, size);
    return {.model = model,
            .normalMatrix = glm::inverseTranspose(glm::mat3(model)),
            .centre = position,
            .radius = 0.5f * glm::length(size),
            .selected = selected};
}

void addBodyVectors(SceneDrawList& list, const Body& body, const ViewerSettings& settings,
                    float radius)
{
    const glm::vec3 centre(body.position);
    // body axes, each sticking out of its face
    if (settings.showAxes) {
        const glm::mat3 rotation = glm::mat3_cast(glm::quat(body.orientation));
        const glm::vec3 half(body.shape.halfExtents());
        const glm::vec3 colours[3] = {palette::kAxisX, palette::kAxisY, palette::kAxisZ};
        for (int axis = 0; axis < 3; ++axis) {
            addArrow(list, centre, rotation[axis] * (1.5f * half[axis] + 0.3f), colours[axis],
                     radius);
        }
    }
    if (settings.showAngularVelocity) {
        addArrow(list, centre, glm::vec3(body.angularVelocity) * settings.vectorScale,
                 palette::kAngularVelocity, radius);
    }
    if (settings.showAngularMomentum) {
        addArrow(list, centre, glm::vec3(body.angularMomentum()) * settings.vectorScale,
                 palette::kAngularMomentum, radius);
    }
}

void addContacts(SceneDrawList& list, const ContactManifold& contacts, float markerScale)
{
    for (int i = 0; i < contacts.pointCount; ++i) {
        list.markers.push_back(
            {.position = glm::vec3(contacts.points[static_cast<std::size_t>(i)].position),
             .colour = palette::kContactVertex,
             .sizePixels = markerScale * kVertexMarkerPixels});
    }
    if (contacts.pointCount > 0) {
        list.markers.push_back({.position = glm::vec3(contacts.averagePoint()),
                                .colour = palette::kContactAverage,
                                .sizePixels = markerScale * kAverageMarkerPixels});
    }
}

/// A square patch of a plane as a thin fixed cuboid: its y axis along the normal, its top face on
/// the plane, wide enough to hold every body's projection.
CuboidInstance planePatchOf(const StaticPlane& plane, const World& world,
                            std::span<const BodyId> bodies)
{
    const glm::vec3 point(plane.point);
    const glm::vec3 normal(plane.normal);
    float half = kPlanePatchMargin;
    for (const BodyId id : bodies) {
        const Body& body = world.body(id);
        const glm::vec3 offset = glm::vec3(body.position) - point;
        half = std::max(half, glm::length(offset - glm::dot(offset, normal) * normal) +
                                  0.5f * static_cast<float>(glm::length(body.shape.size)) +
                                  kPlanePatchMargin);
    }
    // the shortest turn of +y onto the normal (half a turn about x for -y)
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    const glm::vec3 axis = glm::cross(up, normal);
    const float along = glm::dot(up, normal);
    const glm::quat rotation =
        glm::length(axis) > 1e-6f
            ? glm::angleAxis(std::atan2(glm::length(axis), along), glm::normalize(axis))
            : (along > 0.0f ? glm::quat(1.0f, 0.0f, 0.0f, 0.0f) : glm::quat(0.0f, 1.0f, 0.0f, 0.0f));
    const glm::mat4 model =
        glm::scale(glm::translate(glm::mat4(1.0f), point - 0.5f * kPlanePatchThickness * normal) *
                       glm::mat4_cast(rotation),
                   glm::vec3(2.0f * half, kPlanePatchThickness, 2.0f * half));
    return {.model = model,
            .normalMatrix = glm::inverseTranspose(glm::mat3(model)),
            .centre = point,
            .radius = half,
            .selected = false,
            .fixed = true};
}

/// The points where bodies touch each other or a plane in the last step (the contact ledger's
/// resting records, kept when the world records contacts).
void addBodyContacts(SceneDrawList& list, const World& world, float markerScale)
{
    for (const ContactRecord& record : world.contactRecords()) {
        const ContactManifold& manifold = record.manifold;
        if (record.phase != ContactPhase::Resting ||
            (manifold.other.isNull() && manifold.plane < 0)) {
            continue;
        }
        addContacts(list, manifold, markerScale);
    }
}

} // namespace

float contactMarkerScale(std::size_t bodyCount)
{
    // the markers' area shrinks with the number of bodies, down to a third of their size
    const float scale = std::sqrt(10.0f / static_cast<float>(std::max<std::size_t>(bodyCount, 1)));
    return std::clamp(scale, kMinMarkerScale, 1.0f);
}

SceneDrawList buildScene(const World& world, std::span<const BodyId> bodies,
                         std::span<const std::optional<CollisionEvent>> lastCollisions,
                         const ViewerSettings& settings, float referenceHeight)
{
    SceneDrawList list;
    list.gridIsGround = world.ground().has_value();
    list.gridHeight =
        list.gridIsGround ? static_cast<float>(world.ground()->height) : referenceHeight;

    for (const StaticPlane& plane : world.planes()) {
        list.cuboids.push_back(planePatchOf(plane, world, bodies));
    }
    const float markerScale = contactMarkerScale(bodies.size());
    if (settings.showContacts) {
        addBodyContacts(list, world, markerScale);
    }
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const Body& body = world.body(bodies[i]);
        if (body.isStatic()) {
            CuboidInstance fixed = cuboidOf(body, false);
            fixed.fixed = true;
            list.cuboids.push_back(fixed);
            continue;
        }
        list.cuboids.push_back(cuboidOf(body, i == settings.selectedBody && bodies.size() > 1));
        // arrows as thick as suits the body: thin on a small cube, thicker on a large block
        const float arrowRadius = std::clamp(0.02f * list.cuboids.back().radius, 0.015f, 0.15f);
        addBodyVectors(list, body, settings, arrowRadius);

        if (settings.showContacts) {
            addContacts(list, world.contactsOf(bodies[i]), markerScale);
        }
        if (settings.showImpulses && i < lastCollisions.size() && lastCollisions[i]) {
            const CollisionEvent& collision = *lastCollisions[i];
            const glm::vec3 point(collision.manifold.averagePoint());
            addArrow(list, point, glm::vec3(collision.normalImpulse) * settings.impulseScale,
                     palette::kNormalImpulse, 1.5f * arrowRadius, true);
            addArrow(list, point, glm::vec3(collision.frictionImpulse) * settings.impulseScale,
                     palette::kFrictionImpulse, 1.5f * arrowRadius, true);
        }
    }
    return list;
}

} // namespace tumble::viewer
