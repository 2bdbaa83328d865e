// Torque-free rotation: an angular-momentum-conserving splitting (default) and the handouts'
// first-order update.
#include "dynamics/integrator.hpp"

#include "body_state.hpp"

#include <cmath>
#include <limits>

namespace tumble {

namespace {

Vec3 unitAxis(int axis)
{
    Vec3 e(0.0);
    e[axis] = 1.0;
    return e;
}

/// The flow of H = c Pi_k^2 / 2 for time h: the body turns about its own axis k by
/// theta = h c Pi_k, and the body-frame momentum turns the other way (2.6).
void turnAboutBodyAxis(Quat& orientation, Vec3& bodyMomentum, int axis, Real coefficient, Real h)
{
    const Real angle = h * coefficient * bodyMomentum[axis];
    if (angle == 0.0) {
        return;
    }
    // The body turns by +angle and its momentum by -angle: one rotation and its conjugate.
    const Quat turn = axisAngle(unitAxis(axis), angle);
    orientation = orientation * turn;
    bodyMomentum = glm::conjugate(turn) * bodyMomentum;
}

/// The flow of H = |Pi|^2 / (2 I_ref) for time h: a rotation about Pi itself, which leaves the
/// body-frame momentum unchanged (2.5).
void turnAboutMomentum(Quat& orientation, const Vec3& bodyMomentum, Real referenceInertia, Real h)
{
    const Real momentum = glm::length(bodyMomentum);
    if (momentum == 0.0) {
        return;
    }
    orientation = orientation * axisAngle(bodyMomentum / momentum, h * momentum / referenceInertia);
}

/// Largest turn one composition of (2.7) makes, rad, and the most compositions per call: the
/// time-of-impact search evaluates poses many times per sub-step, so the division is capped.
constexpr Real kMaxTurnPerSplit = 0.5;
constexpr Real kMaxSplitPieces = 8.0;

/// The split of (2.7): the reference moment is one of the two closest principal moments; for a
/// symmetric body the other one's term vanishes and the remaining flows commute, so the split is
/// exact.
struct RotationSplit {
    int reference = 0;
    int near = 1;
    int far = 2;
    Real nearCoefficient = 0.0;
    Real farCoefficient = 0.0;
};

RotationSplit chooseSplit(const Vec3& inertiaBody)
{
    RotationSplit split;
    Real closest = std::abs(inertiaBody.x - inertiaBody.y);
    if (std::abs(inertiaBody.x - inertiaBody.z) < closest) {
        closest = std::abs(inertiaBody.x - inertiaBody.z);
        split.near = 2;
        split.far = 1;
    }
    if (std::abs(inertiaBody.y - inertiaBody.z) < closest) {
        split.reference = 1;
        split.near = 2;
        split.far = 0;
    }
    const Real referenceInverse = 1.0 / inertiaBody[split.reference];
    split.nearCoefficient = 1.0 / inertiaBody[split.near] - referenceInverse;
    split.farCoefficient = 1.0 / inertiaBody[split.far] - referenceInverse;
    return split;
}

void rotateExact(Quat& orientation, Vec3& angularVelocity, const Vec3& inertiaBody, Real dt)
{
    if (inertiaBody.x == inertiaBody.y && inertiaBody.y == inertiaBody.z) {
        // A spherical top (a cube): w = L / I stays constant and the flow (2.5) is one rotation
        // by |w| dt about it, in the world frame; w is left exactly as it was.
        const Real speed = glm::length(angularVelocity);
        if (speed > 0.0) {
            orientation =
                glm::normalize(axisAngle(angularVelocity / speed, speed * dt) * orientation);
        }
        return;
    }
    const RotationSplit split = chooseSplit(inertiaBody);
    const Real referenceInertia = inertiaBody[split.reference];
    // (2.4): body-frame angular momentum Pi = I0 R^T w; the world momentum R Pi is what every
    // sub-flow below conserves.
    Vec3 bodyMomentum = inertiaBody * (glm::conjugate(orientation) * angularVelocity);
    if (split.nearCoefficient == 0.0) {
        // A symmetric body: B is the identity and A commutes with C, so A(dt) C(dt) is the exact
        // flow for any dt, in one composition and two rotations instead of three (2.7).
        turnAboutBodyAxis(orientation, bodyMomentum, split.far, split.farCoefficient, dt);
        turnAboutMomentum(orientation, bodyMomentum, referenceInertia, dt);
        orientation = glm::normalize(orientation);
        angularVelocity = orientation * (bodyMomentum / inertiaBody);
        return;
    }
    // (2.7a): the split's energy error grows like (turn per composition)^2, so a body spun up
    // past kMaxTurnPerSplit per step (an impact at the tip of a thin rod can do it) is turned in
    // several compositions; ordinary steps turn far less and take exactly one. The turn rate is
    // the bound of rotationBounds' pieces, so the time of impact stays consistent.
    const Real turnRate = glm::length(bodyMomentum) *
                          (1.0 / referenceInertia + std::abs(split.nearCoefficient) +
                           std::abs(split.farCoefficient));
    const int pieces = static_cast<int>(std::min(
        kMaxSplitPieces, std::max(1.0, std::ceil(turnRate * std::abs(dt) / kMaxTurnPerSplit))));
    const Real h = dt / pieces;
    for (int piece = 0; piece < pieces; ++piece) {
        // Strang composition (2.7): A(h/2) B(h/2) C(h) B(h/2) A(h/2), second order and symmetric.
        turnAboutMomentum(orientation, bodyMomentum, referenceInertia, 0.5 * h);
        turnAboutBodyAxis(orientation, bodyMomentum, split.near, split.nearCoefficient, 0.5 * h);
        turnAboutBodyAxis(orientation, bodyMomentum, split.far, split.farCoefficient, h);
        turnAboutBodyAxis(orientation, bodyMomentum, split.near, split.nearCoefficient, 0.5 * h);
        turnAboutMomentum(orientation, bodyMomentum, referenceInertia, 0.5 * h);
    }
    orientation = glm::normalize(orientation);
    angularVelocity = orientation * (bodyMomentum / inertiaBody);
}

void rotateHandout(Quat& orientation, const Vec3& angularVelocity, Real dt)
{
    // (2.8): R <- R + dt [w]x R, then Gram-Schmidt so R stays a rotation.
    Mat3 rotation = glm::mat3_cast(orientation);
    rotation += dt * skew(angularVelocity) * rotation;
    const Vec3 column0 = glm::normalize(rotation[0]);
    // The columns stay independent: I + dt [w]x has determinant 1 + |w dt|^2, never zero.
    const Vec3 column1 = glm::normalize(rotation[1] - glm::dot(column0, rotation[1]) * column0);
    rotation = Mat3(column0, column1, glm::cross(column0, column1));
    const Quat updated = glm::normalize(glm::quat_cast(rotation));
    // q and -q are the same rotation; keep the sign continuous so printed quaternions do not jump.
    orientation = glm::dot(updated, orientation) < 0.0 ? -updated : updated;
}

} // namespace

void integrateRotation(Quat& orientation, Vec3& angularVelocity, const Vec3& inertiaBody, Real dt,
                       Integrator integrator)
{
    // A flow over no time is the identity. The steps below would still round the pose (Gram-
    // Schmidt and quat_cast, or renormalising q and recomputing w from Pi), by an ulp that moves
    // a vertex 500 m out by 3e-14 m; the time of impact measures the clearance at s = 0 with this
    // function and must see exactly the heights the world tested against the impact tolerance
    // (04-detection.md, (4.3)).
    if (dt == 0.0) {
        return;
    }
    switch (integrator) {
    case Integrator::Exact: rotateExact(orientation, angularVelocity, inertiaBody, dt); break;
    case Integrator::Handout: rotateHandout(orientation, angularVelocity, dt); break;
    }
}

RotationBounds rotationBounds(const Quat& orientation, const Vec3& angularVelocity,
                              const Vec3& inertiaBody, Real maxStep, Integrator integrator)
{
    RotationBounds rates;
    if (integrator == Integrator::Handout) {
        rates.aboutAnyAxis = glm::length(angularVelocity);
        return rates;
    }
    // (4.4): the pose after s is the composition (2.7) A(s/2) B(s/2) C(s) B(s/2) A(s/2); its
    // turning rate in s is at most the sum of the rates at which the pieces' angles (and the last
    // A's axis) change. The body-frame momentum Pi keeps |Pi| throughout; B turns it about the
    // near axis (keeping Pi_near), C about the far axis (keeping Pi_far), so over s <= maxStep the
    // components entering C and the second B stay near their start values. Bounding them by |Pi|
    // instead would be valid but, for a long thin body (tiny I_far, huge c_far), thousands of
    // times too large for the time of impact to converge.
    const RotationSplit split = chooseSplit(inertiaBody);
    const Vec3 bodyMomentum = inertiaBody * (glm::conjugate(orientation) * angularVelocity);
    const Real momentum = glm::length(bodyMomentum);
    const Real cNear = std::abs(split.nearCoefficient);
    const Real cFar = std::abs(split.farCoefficient);
    const Real piNear = std::abs(bodyMomentum[split.near]);
    const Real piFar = std::abs(bodyMomentum[split.far]);
    const Real piReference = std::abs(bodyMomentum[split.reference]);
    const Real h = maxStep;
    // First B: angle (s/2) c_near Pi_near.
    const Real rateNear1 = 0.5 * cNear * piNear;
    // C: angle s c_far Pi_far(s), Pi_far(s) turned by the first B by at most h rateNear1.
    const Real piFarBound =
        std::min(momentum, piFar + piReference * std::min(1.0, h * rateNear1));
    const Real rateFar = cFar * (piFarBound + h * momentum * rateNear1);
    // Second B: angle (s/2) c_near Pi_near(s), Pi_near(s) turned by C by at most h rateFar.
    const Real piNearBound = std::min(momentum, piNear + momentum * std::min(1.0, h * rateFar));
    const Real rateNear2 = 0.5 * cNear * (piNearBound + h * momentum * (rateFar + rateNear1));
    // The two A: angle (s/2) |Pi| / I_ref each; the second one's axis Pi(s)/|Pi| turns at most
    // at the sum of the B and C rates.
    const Real rateMomentum = momentum / inertiaBody[split.reference];
    const Real axisTurn =
        2.0 * std::min(1.0, 0.5 * h * rateMomentum) * (rateNear1 + rateFar + rateNear2);
    rates.aboutAnyAxis = rateMomentum + axisTurn;
    rates.aboutNearAxis = rateNear1 + rateNear2;
    rates.aboutFarAxis = rateFar;
    rates.nearAxis = split.near;
    rates.farAxis = split.far;
    if (split.nearCoefficient == 0.0) {
        // (4.4a): a symmetric (or spherical) top turns at a = |Pi| / I_ref about the fixed L and
        // at c = c_far Pi_far about its own axis e, so w = a L/|L| + c e with |w| constant and
        // dw/ds = c (w x e), of size at most a |c|.
        rates.curvature = glm::dot(angularVelocity, angularVelocity) +
                          rateMomentum * std::abs(split.farCoefficient * bodyMomentum[split.far]);
    }
    return rates;
}

Real rotationEnergyErrorBound(const Quat& orientation, const Vec3& angularVelocity,
                              const Vec3& inertiaBody, Real h)
{
    // (2.7b): A(h/2) turns the body about Pi and leaves Pi itself alone (|Pi|^2 is a Casimir),
    // so the energy, a function of Pi, sees only the Strang splitting B(h/2) C(h) B(h/2) of
    // B + C. Its modified energy is B + C + h^2 (-{B,{B,C}} / 24 + {C,{C,B}} / 12) + O(h^4), with
    // {B,{B,C}} = c_near^2 c_far Pi_near^2 (Pi_ref^2 - Pi_far^2) up to sign, at most
    // c_near^2 |c_far| |Pi|^4 / 4, and the same with near and far exchanged. The energy stays
    // within twice the largest difference of the two.
    const RotationSplit split = chooseSplit(inertiaBody);
    const Vec3 bodyMomentum = inertiaBody * (glm::conjugate(orientation) * angularVelocity);
    const Real momentumSquared = glm::dot(bodyMomentum, bodyMomentum);
    const Real cNear = std::abs(split.nearCoefficient);
    const Real cFar = std::abs(split.farCoefficient);
    return 4.0 * h * h * momentumSquared * momentumSquared * cNear * cFar *
           (cNear / 96.0 + cFar / 48.0);
}

void integrateRotation(Body& body, Real dt, Integrator integrator)
{
    integrateRotation(body.orientation, body.angularVelocity, body.inertiaBody(), dt, integrator);
    refreshWorldInertia(body);
}

} // namespace tumble
