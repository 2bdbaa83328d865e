// Axis-aligned bounding boxes: of a cuboid at one pose, and of everything a cuboid covers during
// a step (docs/physics/10-broad-phase.md, (10.1)-(10.3)).
#pragma once

#include "tumble/math.hpp"

#include <algorithm>

namespace tumble {

/// The closed box min <= p <= max, componentwise, in world axes (m).
struct Aabb {
    Vec3 min{0.0};
    Vec3 max{0.0};
};

/// Whether the closed boxes share a point: touching boxes (a shared face, edge or corner) overlap.
inline bool overlaps(const Aabb& a, const Aabb& b)
{
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y &&
           b.min.y <= a.max.y && a.min.z <= b.max.z && b.min.z <= a.max.z;
}

/// The smallest box containing both.
inline Aabb merged(const Aabb& a, const Aabb& b)
{
    return Aabb{glm::min(a.min, b.min), glm::max(a.max, b.max)};
}

/// The box grown by `margin` (m) on every side.
inline Aabb expanded(const Aabb& box, Real margin)
{
    return Aabb{box.min - Vec3(margin), box.max + Vec3(margin)};
}

/// Total area of the six faces (m^2).
inline Real surfaceArea(const Aabb& box)
{
    const Vec3 size = box.max - box.min;
    return 2.0 * (size.x * size.y + size.y * size.z + size.z * size.x);
}

/// The exact box of a cuboid with the given half extents (m) at `pose`: half width
/// sum_k |R_ik| h_k along world axis i (10.1).
Aabb cuboidAabb(const Transform& pose, const Vec3& halfExtents);

/// A box containing every point of the cuboid at every time s in [0, dt] of a step that starts
/// at `pose` and moves ballistically, x + v s + g s^2/2, while turning by an angle of at most
/// |angularVelocity| s, grown by `margin` (10.2)-(10.3). `angularVelocity` (rad/s) must bound the
/// angular speed over the whole step; dt >= 0 (s).
Aabb sweptCuboidAabb(const Transform& pose, const Vec3& halfExtents, const Vec3& velocity,
                     const Vec3& gravity, const Vec3& angularVelocity, Real dt, Real margin);

} // namespace tumble
