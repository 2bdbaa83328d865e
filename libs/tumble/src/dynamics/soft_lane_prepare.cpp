// The soft step's rows four manifolds at a time (docs/physics/12-soft-step.md, (12.3), (12.9)).
#include "dynamics/soft_lane_prepare.hpp"

namespace tumble::soft_rows {

namespace {

/// glm's cross, lane by lane: (a.y b.z - b.y a.z, a.z b.x - b.z a.x, a.x b.y - b.x a.y).
TUMBLE_WIDE_INLINE Wide3 cross(const Wide3& a, const Wide3& b)
{
    return {a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y};
}

/// A symmetric or general 3x3 matrix of each lane, by glm's columns.
struct WideMat3 {
    Wide3 column[3];
};

/// glm's matrix times vector: row r is (m[0][r] v.x + m[1][r] v.y) + m[2][r] v.z.
TUMBLE_WIDE_INLINE Wide3 times(const WideMat3& m, const Wide3& v)
{
    return {m.column[0].x * v.x + m.column[1].x * v.y + m.column[2].x * v.z,
            m.column[0].y * v.x + m.column[1].y * v.y + m.column[2].y * v.z,
            m.column[0].z * v.x + m.column[1].z * v.y + m.column[2].z * v.z};
}

TUMBLE_WIDE_INLINE Wide3 scaled(const Wide3& v, Wide s) { return {v.x * s, v.y * s, v.z * s}; }

TUMBLE_WIDE_INLINE Wide3 chosen(Mask where, const Wide3& yes, const Wide3& no)
{
    return {select(where, yes.x, no.x), select(where, yes.y, no.y), select(where, yes.z, no.z)};
}

/// The inverse inertias of the lanes' bodies on one side.
TUMBLE_WIDE_INLINE WideMat3 inverseInertias(const std::array<std::uint32_t, kLanes>& index,
                                            std::span<const SoftBody> bodies)
{
    WideMat3 m;
    for (int lane = 0; lane < kLanes; ++lane) {
        const Mat3& inertia = bodies[index[lane]].invInertia;
        for (int c = 0; c < 3; ++c) {
            lanes::setLane(m.column[c], lane, inertia[c]);
        }
    }
    return m;
}

/// A point's normal row (11.2) and lever arm (12.5), where the point is present.
TUMBLE_WIDE_INLINE void preparePoint(const LaneBlock& block, LanePoint& p,
                                     const LaneCentres& centres, const WideMat3& inertiaA,
                                     const WideMat3& inertiaB)
{
    const Wide3 angularA = cross(p.anchorA, block.normal);
    const Wide3 angularB = cross(p.anchorB, block.normal);
    const Wide3 responseA = times(inertiaA, angularA);
    const Wide3 responseB = times(inertiaB, angularB);
    const Wide k = block.invMassA + block.invMassB + dot(angularA, responseA) +
                   dot(angularB, responseB);
    const Wide mass = select(less(splat(0.0), k), splat(1.0) / k, splat(0.0));
    const Wide3 fromCentre = minus(p.anchorB, centres.b);
    const Wide3 inPlane = minus(fromCentre, scaled(block.normal, dot(fromCentre, block.normal)));
    const Mask present = p.active;
    p.angularA = chosen(present, angularA, p.angularA);
    p.angularB = chosen(present, angularB, p.angularB);
    p.responseA = chosen(present, responseA, p.responseA);
    p.responseB = chosen(present, responseB, p.responseB);
    p.normalMass = select(present, mass, p.normalMass);
    p.leverArm = select(present, squareRoot(dot(inPlane, inPlane)), p.leverArm);
}

} // namespace

TUMBLE_WIDE_CLONES
void prepareLaneRows(LaneBlock& block, const LaneCentres& centres,
                     std::span<const SoftBody> bodies)
{
    const WideMat3 inertiaA = inverseInertias(block.bodyA, bodies);
    const WideMat3 inertiaB = inverseInertias(block.bodyB, bodies);
    for (LanePoint& p : block.points) {
        preparePoint(block, p, centres, inertiaA, inertiaB);
    }
    block.angularA1 = cross(centres.a, block.tangent1);
    block.angularA2 = cross(centres.a, block.tangent2);
    block.angularB1 = cross(centres.b, block.tangent1);
    block.angularB2 = cross(centres.b, block.tangent2);
    block.responseA1 = times(inertiaA, block.angularA1);
    block.responseA2 = times(inertiaA, block.angularA2);
    block.responseB1 = times(inertiaB, block.angularB1);
    block.responseB2 = times(inertiaB, block.angularB2);
    block.twistResponseA = times(inertiaA, block.normal);
    block.twistResponseB = times(inertiaB, block.normal);
    // (11.3) at the centre
    const Wide massSum = block.invMassA + block.invMassB;
    const Wide k11 = massSum + dot(block.angularA1, block.responseA1) +
                     dot(block.angularB1, block.responseB1);
    const Wide k12 =
        dot(block.angularA1, block.responseA2) + dot(block.angularB1, block.responseB2);
    const Wide k22 = massSum + dot(block.angularA2, block.responseA2) +
                     dot(block.angularB2, block.responseB2);
    block.tangentK[0] = k11;
    block.tangentK[1] = k12;
    block.tangentK[2] = k22;
    const Wide determinant = k11 * k22 - k12 * k12;
    const Mask invertible = less(splat(0.0), determinant);
    block.tangentMass[0] = select(invertible, k22 / determinant, splat(0.0));
    block.tangentMass[1] = select(invertible, -k12 / determinant, splat(0.0));
    block.tangentMass[2] = select(invertible, k11 / determinant, splat(0.0));
    block.twistK = dot(block.normal, block.twistResponseA) + dot(block.normal, block.twistResponseB);
    block.twistMass =
        select(less(splat(0.0), block.twistK), splat(1.0) / block.twistK, splat(0.0));
}

} // namespace tumble::soft_rows
