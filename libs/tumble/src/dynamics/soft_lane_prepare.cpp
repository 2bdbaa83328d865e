// The soft step's rows a block of manifolds at a time (docs/physics/12-soft-step.md, (12.3),
// (12.9)).
#include "dynamics/soft_lane_prepare.hpp"

namespace tumble::soft_rows {

namespace {

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

/// A point's normal row's angular parts r x n and their images I^-1 (r x n) on each side.
struct LaneRow {
    LaneAngular angular;
    Wide3 responseA, responseB;
};

/// A point's normal row (11.2) and lever arm (12.5), where the point is present.
TUMBLE_WIDE_INLINE void preparePoint(const LaneBlock& block, LanePoint& p, const LaneRow& row)
{
    const Wide k = block.invMassA + block.invMassB + dot(row.angular.a, row.responseA) +
                   dot(row.angular.b, row.responseB);
    const Wide mass = select(less(splat(0.0), k), splat(1.0) / k, splat(0.0));
    const Wide3 fromCentre = minus(p.anchorB, block.centreB);
    const Wide3 inPlane = minus(fromCentre, scaled(block.normal, dot(fromCentre, block.normal)));
    const Mask present = p.active;
    p.normalK = select(present, k, p.normalK);
    p.normalMass = select(present, mass, p.normalMass);
    p.leverArm = select(present, squareRoot(dot(inPlane, inPlane)), p.leverArm);
}

} // namespace

TUMBLE_WIDE_CLONES
void prepareLaneRows(LaneBlock& block, std::span<const SoftBody> bodies)
{
    const WideMat3 inertiaA = inverseInertias(block.bodyA, bodies);
    const WideMat3 inertiaB = inverseInertias(block.bodyB, bodies);
    LaneRow rows[4];
    for (int k = 0; k < 4; ++k) {
        LanePoint& p = block.points[k];
        rows[k].angular = pointAngular(block, p);
        rows[k].responseA = times(inertiaA, rows[k].angular.a);
        rows[k].responseB = times(inertiaB, rows[k].angular.b);
        preparePoint(block, p, rows[k]);
    }
    // (12.4): the couplings of each two points, where both are present
    for (int i = 0; i < 4; ++i) {
        for (int j = i + 1; j < 4; ++j) {
            const Wide coupling = block.invMassA + block.invMassB +
                                  dot(rows[i].angular.a, rows[j].responseA) +
                                  dot(rows[i].angular.b, rows[j].responseB);
            Wide& kept = block.normalCoupling[couplingIndex(i, j)];
            kept = select(block.points[j].active, coupling, kept);
        }
    }
    const Wide3 angularA1 = cross(block.centreA, block.tangent1);
    const Wide3 angularA2 = cross(block.centreA, block.tangent2);
    const Wide3 angularB1 = cross(block.centreB, block.tangent1);
    const Wide3 angularB2 = cross(block.centreB, block.tangent2);
    block.inertiaA = inertiaA;
    block.inertiaB = inertiaB;
    const Wide3 responseA1 = times(inertiaA, angularA1);
    const Wide3 responseA2 = times(inertiaA, angularA2);
    const Wide3 responseB1 = times(inertiaB, angularB1);
    const Wide3 responseB2 = times(inertiaB, angularB2);
    block.twistResponseA = times(inertiaA, block.normal);
    block.twistResponseB = times(inertiaB, block.normal);
    // (11.3) at the centre
    const Wide massSum = block.invMassA + block.invMassB;
    const Wide k11 = massSum + dot(angularA1, responseA1) + dot(angularB1, responseB1);
    const Wide k12 = dot(angularA1, responseA2) + dot(angularB1, responseB2);
    const Wide k22 = massSum + dot(angularA2, responseA2) + dot(angularB2, responseB2);
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
