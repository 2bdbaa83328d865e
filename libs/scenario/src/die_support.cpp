// The face of a die at rest, read against what it rests on: the ground, a plane, a static body
// (a tray's floor, a tower's baffle) or another die. A die leaning on a wall or on another die
// with no face flat on its support is cocked, and a tray's rules would reroll it.
#include "tumble/scenario/throw_dice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace tumble::scenario {

namespace {

/// Surfaces within this distance of the die (besides the contact tolerance) touch it, m.
constexpr Real kTouchGap = 1e-4;

/// The outward normal of the face of cuboid `other` that the point `p` lies beyond the most:
/// for a die resting on a box, the normal of the face it rests on.
Vec3 boxFaceNormalToward(const Body& other, const Vec3& p)
{
    const Mat3 axes = other.rotation();
    const Vec3 local = glm::transpose(axes) * (p - other.position);
    const Vec3 half = other.shape.halfExtents();
    int best = 0;
    Real outside = -std::numeric_limits<Real>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
        const Real beyond = std::abs(local[axis]) - half[axis];
        if (beyond > outside) {
            outside = beyond;
            best = axis;
        }
    }
    return (local[best] < 0.0 ? -1.0 : 1.0) * axes[best];
}

/// Up: against gravity, or +y without gravity.
Vec3 upOf(const World& world)
{
    const Vec3& g = world.settings().gravity;
    const Real length = glm::length(g);
    return length > 0.0 ? -g / length : Plane::normal();
}

/// The support's outward normal: of the touching surfaces, the one nearest to up; up when none
/// touches (a die cannot rest on nothing, so this is only a fallback).
Vec3 supportNormal(const World& world, BodyId die)
{
    const Body& body = world.body(die);
    const Vec3 half = body.shape.halfExtents();
    const Transform pose{body.position, body.orientation};
    const Vec3 up = upOf(world);
    const Real reach = world.settings().contactTolerance + kTouchGap;
    Vec3 best = up;
    Real bestAlignment = -2.0;
    const auto consider = [&](const Vec3& normal, Real depth) {
        if (depth > -reach && glm::dot(normal, up) > bestAlignment) {
            bestAlignment = glm::dot(normal, up);
            best = normal;
        }
    };
    if (const std::optional<Plane>& ground = world.ground()) {
        const StaticPlane plane{Vec3(0.0, ground->height, 0.0), Plane::normal(), {}};
        consider(plane.normal, cuboidHalfSpaceDepth(pose, half, plane));
    }
    for (const StaticPlane& plane : world.planes()) {
        consider(plane.normal, cuboidHalfSpaceDepth(pose, half, plane));
    }
    for (const BodyId id : world.bodyIds()) {
        if (id.index == die.index) {
            continue;
        }
        const Body& other = world.body(id);
        const Real depth = cuboidOverlapDepth(pose, half, {other.position, other.orientation},
                                              other.shape.halfExtents());
        if (depth > -reach) {
            consider(boxFaceNormalToward(other, body.position), depth);
        }
    }
    return best;
}

} // namespace

DieOutcome readDieAtRest(const World& world, BodyId die)
{
    const Body& body = world.body(die);
    const Vec3 normal = supportNormal(world, die);
    const CuboidFace face = faceAlong(body.orientation, -normal);
    // the face's outward normal in world axes, and its angle to the support's inward normal
    const auto index = static_cast<int>(face);
    Vec3 local(0.0);
    local[index / 2] = index % 2 == 0 ? 1.0 : -1.0;
    const Vec3 faceNormal = body.rotation() * local;
    const Real flatness = std::cos(kCockedDegrees * std::numbers::pi / 180.0);
    DieOutcome outcome;
    outcome.settled = 1;
    outcome.face = static_cast<std::uint8_t>(face);
    outcome.cocked = glm::dot(faceNormal, -normal) < flatness ? 1 : 0;
    return outcome;
}

} // namespace tumble::scenario
