// The soft step's contact rows: soft non-penetration with a bounded push-out, a friction disc,
// a relax pass without bias and restitution after the sub-steps (docs/physics/12-soft-step.md).
#pragma once

#include "dynamics/solver_point.hpp"
#include "tumble/math.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace tumble {

/// A body as the soft step sees it: velocities, how far it moved since the step began, and its
/// inverse mass properties, held at the step's start (12.4). Static geometry is the one body of
/// zero inverses, which never moves.
struct SoftBody {
    Vec3 linearVelocity{0.0};
    Vec3 angularVelocity{0.0};
    /// Displacement of the centre of mass since the step began, m.
    Vec3 deltaPosition{0.0};
    /// Orientation now, and its rotation since the step began, R(q) R(q0)^T.
    Quat orientation{1.0, 0.0, 0.0, 0.0};
    Mat3 deltaRotation{1.0};
    Real invMass = 0.0;
    Mat3 invInertia{0.0};
};

/// (12.2): the coefficients of a soft row for a spring of `hertz` and `dampingRatio` advanced by
/// implicit Euler over h: the bias rate on the gap, the share of the rigid effective mass and
/// the share of the accumulated impulse taken back each solve. hertz = 0 is a rigid row.
struct Softness {
    Real biasRate = 0.0;
    Real massScale = 1.0;
    Real impulseScale = 0.0;
};

Softness makeSoftness(Real hertz, Real dampingRatio, Real h);

/// One point of a soft manifold. The anchors are the offsets of the point from each centre of
/// mass at the step's start; the gap now is n . ((dpB + dRB rB) - (dpA + dRA rA)) plus
/// `baseSeparation` (12.3).
struct SoftPoint {
    Vec3 anchorA{0.0};
    Vec3 anchorB{0.0};
    /// The normal row's angular parts rA x n, rB x n and their images under the inverse
    /// inertias (11.2).
    Vec3 angularA{0.0};
    Vec3 angularB{0.0};
    Vec3 responseA{0.0};
    Vec3 responseB{0.0};
    Real baseSeparation = 0.0;
    /// The normal row's K (11.2) and its inverse, the effective mass.
    Real normalK = 0.0;
    Real normalMass = 0.0;
    /// Distance of the point from the manifold's centre, m: its lever for twist friction (12.5).
    Real leverArm = 0.0;
    /// Normal velocity when the step began, m/s: what restitution reverses (12.6).
    Real relativeVelocity = 0.0;
    Real normalImpulse = 0.0;
    /// Largest normal impulse any solve of the step applied: restitution acts only where the
    /// point pushed.
    Real maxNormalImpulse = 0.0;
    /// Work of the point's normal impulses over the step, J (8.2).
    Real normalWork = 0.0;
};

/// The index in SoftManifold::normalCoupling of points i and j, i != j, in either order.
constexpr int couplingIndex(int i, int j)
{
    const int low = i < j ? i : j;
    const int high = i < j ? j : i;
    return low == 0 ? high - 1 : low == 1 ? high + 1 : 5;
}

/// A contact of the soft step: two bodies, one normal, up to four points, and one friction
/// row pair and one twist row at the points' centre (12.5).
struct SoftManifold {
    std::uint32_t bodyA = 0;
    std::uint32_t bodyB = 0;
    int pointCount = 0;
    /// Whether one side is static geometry: such rows are twice as stiff (12.2).
    bool againstStatic = false;
    Vec3 normal{0.0, 1.0, 0.0};
    Vec3 tangent1{1.0, 0.0, 0.0};
    Vec3 tangent2{0.0, 0.0, 1.0};
    Real friction = 0.0;
    Real restitution = 0.0;
    /// The points' centre as offsets from each centre of mass, m.
    Vec3 centreA{0.0};
    Vec3 centreB{0.0};
    /// The twist row's I_A^-1 n and I_B^-1 n (11.2). The friction rows are applied and read
    /// through the centres (12.5a).
    Vec3 twistResponseA{0.0};
    Vec3 twistResponseB{0.0};
    /// K_t at the centre over (t1, t2) and its inverse, as (11, 12, 22) (11.3).
    std::array<Real, 3> tangentK{};
    std::array<Real, 3> tangentMass{};
    /// How an impulse along the normal at point j changes the normal velocity at point i < j:
    /// K_ij = mA + mB + (rA_i x n) . IA^-1 (rA_j x n) + (rB_i x n) . IB^-1 (rB_j x n), for
    /// (i, j) = (0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3) (12.4).
    std::array<Real, 6> normalCoupling{};
    /// n . (IA^-1 + IB^-1) n and its inverse: the twist row's K and effective mass.
    Real twistK = 0.0;
    Real twistMass = 0.0;
    Real frictionImpulse1 = 0.0;
    Real frictionImpulse2 = 0.0;
    Real twistImpulse = 0.0;
    /// Work of the friction and twist impulses over the step, J (8.2).
    Real frictionWork = 0.0;
    std::array<SoftPoint, 4> points{};
};

/// The velocity of body b's point at `anchorB` relative to body a's at `anchorA` (12.3).
inline Vec3 relativeVelocityAt(const SoftBody& a, const SoftBody& b, const Vec3& anchorA,
                               const Vec3& anchorB)
{
    return b.linearVelocity + glm::cross(b.angularVelocity, anchorB) - a.linearVelocity -
           glm::cross(a.angularVelocity, anchorA);
}

/// (6.2) at the manifold's centre: the static coefficient while the faces do not slide, the
/// kinetic one when they do; `centreVelocity` is relativeVelocityAt the centre.
inline Real frictionAtCentre(const Vec3& centreVelocity, const Vec3& normal, Real staticFriction,
                             Real kineticFriction)
{
    const Vec3 sliding = centreVelocity - glm::dot(normal, centreVelocity) * normal;
    return lengthSquared(sliding) < kStickingSpeedSquared ? staticFriction : kineticFriction;
}

/// A manifold kept from the last step started again (12.5b): each point's approach speed and
/// the friction coefficient from the velocities now, the step's work and largest impulses
/// zero; its rows and impulses stay as they are.
void restartSoftManifold(SoftManifold& manifold, std::span<const SoftBody> bodies,
                         Real staticFriction, Real kineticFriction);

/// Fills in a manifold's centre, the mean of its points' anchors on each side (12.5).
void centreSoftManifold(SoftManifold& manifold);

/// Fills in a manifold's centre, its normal rows' angular parts, masses and couplings, and its
/// tangential and twist masses from its points' anchors, normal, tangents and the bodies' inverse masses and
/// inertias. (SoftLanes builds the same rows a block of manifolds at a time as it packs them.)
void prepareSoftRows(SoftManifold& manifold, std::span<const SoftBody> bodies);

/// What one solve pass reads besides the rows: the sub-step's softness for contacts between
/// dynamic bodies and against static geometry, 1 / h, and the push-out's speed bound.
struct SoftSolveSettings {
    Softness dynamicSoftness{};
    Softness staticSoftness{};
    Real inverseSubstep = 0.0;
    Real pushSpeed = 0.0;
};

/// A colour of fewer manifolds than this is swept by one thread: handing it out would cost more
/// than sweeping it.
inline constexpr std::size_t kThreadedColourManifolds = 256;

/// The manifolds' order for the passes: colour c is manifolds [offsets[c], offsets[c + 1]) and
/// no two of them move the same dynamic body; the last group is the overflow, swept in order.
/// With no offsets every pass goes in order.
struct SoftColours {
    std::vector<std::uint32_t> offsets;
    /// (12.9): the first halfColours[0] colours hold only contacts among the first half of the
    /// island's bodies, the next halfColours[1] only contacts among the second half; the rest
    /// cross between the halves. Both 0 where the island is not split.
    std::array<std::uint32_t, 2> halfColours{0, 0};
    /// The first body of the second half (the island's order); 0 where it is not split.
    std::uint32_t halfSplit = 0;
};

class SoftLanes;

/// Applies each manifold's accumulated impulses to its bodies (12.5), and adds their work to
/// the points' and the manifold's (12.8). With `lanes` (packed with
/// these colours) the colours are read from and written to the lanes, and `manifolds` holds
/// only the overflow group, from its first manifold.
void warmStartSoft(std::span<SoftManifold> manifolds, std::span<SoftBody> bodies,
                   const SoftColours& colours, int threads, SoftLanes* lanes = nullptr);

/// One Gauss-Seidel pass over the manifolds in `colours` order: each point's normal row, soft and biased
/// towards closing its gap when `useBias` (12.4), rigid and unbiased when not (the relax pass);
/// in either pass then the manifold's twist row and its friction disc of radius mu sum lambda_n
/// (12.5).
/// `lanes` as for warmStartSoft: the same bits, a block of a colour's manifolds at a time.
void solveSoft(std::span<SoftManifold> manifolds, std::span<SoftBody> bodies,
               const SoftSolveSettings& settings, bool useBias, const SoftColours& colours,
               int threads, SoftLanes* lanes = nullptr);

/// (12.6): each point that pushed and began the step approaching faster than `threshold` gets
/// the normal impulse that makes it leave at e times its approach speed, never pulling.
/// `lanes` as for warmStartSoft.
void restituteSoft(std::span<SoftManifold> manifolds, std::span<SoftBody> bodies,
                   Real threshold, const SoftColours& colours, int threads,
                   SoftLanes* lanes = nullptr);

/// (12.6): whether a point restitution acts on: it began the step approaching faster than
/// `threshold` (relativeVelocity < -threshold) and pushed in the sub-steps.
inline bool bounces(Real relativeVelocity, Real maxNormalImpulse, Real threshold)
{
    return !(relativeVelocity > -threshold || maxNormalImpulse == 0.0);
}

/// restituteSoft on one manifold of elasticity other than zero; a manifold none of whose points
/// bounces is left as it is.
void restituteManifold(SoftManifold& manifold, std::span<SoftBody> bodies, Real threshold);

/// What a step leaves of a contact: its impulses for the next step's warm start (12.5) and its
/// work for the ledgers (8.2).
struct SoftContactResult {
    int pointCount = 0;
    std::array<Real, 4> normalImpulses{};
    std::array<Real, 4> normalWork{};
    /// lambda_t1 t1 + lambda_t2 t2.
    Vec3 frictionImpulse{0.0};
    Real twistImpulse = 0.0;
    Real frictionWork = 0.0;
};

SoftContactResult softResultOf(const SoftManifold& manifold);

} // namespace tumble
