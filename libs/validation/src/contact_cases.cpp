// Cases with the ground: bounces, an edge impact with and without friction, sliding to rest,
// tipping (docs/validation.md, sections 6-9).
#include "case_support.hpp"

#include "tumble/shape.hpp"

#include <cmath>
#include <numbers>

namespace tumble::validation {
namespace {

std::vector<Quantity> bounces(Real dt)
{
    // (V6.1)-(V6.3): dropped face down from clearance h, impact k at T (1 + 2e + ... + 2e^(k-1)),
    // apex k at h e^(2k), T = sqrt(2h/g).
    const Real clearance = 2.0;
    const Real restitution = 0.8;
    World world = makeWorld(WorldSettings{}, true);
    const BodyId id = world.createBody(withFault(BodyDef{
        .position = Vec3(0, 1 + clearance, 0), .material = {.restitution = restitution, .friction = 0.3}}));
    const Body& body = world.body(id);
    std::vector<Real> impacts;
    std::vector<Real> apexes;
    Real previousVelocity = 0.0;
    for (long long i = 0; i < std::llround(4.0 / dt); ++i) {
        world.step(dt);
        for (const CollisionEvent& event : world.collisions()) {
            impacts.push_back(event.time);
        }
        const Real vy = body.linearVelocity.y;
        if (previousVelocity > 0.0 && vy <= 0.0) {
            apexes.push_back(body.position.y - 1.0 + vy * vy / (2.0 * kGravity));
        }
        previousVelocity = vy;
    }
    impacts.resize(3, 0.0);
    apexes.resize(3, 0.0);
    const Real fall = std::sqrt(2.0 * clearance / kGravity);
    std::vector<Quantity> result;
    Real impactTime = fall;
    for (int k = 0; k < 3; ++k) {
        const std::string index = std::to_string(k + 1);
        result.push_back(quantity("apex " + index, clearance * std::pow(restitution, 2 * (k + 1)),
                                  apexes[k], 1e-6, "m"));
        result.push_back(quantity("impact " + index + " time", impactTime, impacts[k], 1e-6, "s"));
        impactTime += 2.0 * std::pow(restitution, k + 1) * fall;
    }

    // (V6.4): the bounces add up to T (1 + e) / (1 - e). The series is followed until the
    // approach falls below the restitution threshold; from the last restituted impact (time t_N,
    // speed a_N) the rest of the series is 2 e a_N / (g (1 - e)).
    const Real settleRestitution = 0.5;
    World settling = makeWorld(WorldSettings{}, true);
    settling.createBody(withFault(BodyDef{
        .position = Vec3(0, 2, 0), .material = {.restitution = settleRestitution, .friction = 0.3}}));
    Real limit = 0.0;
    for (long long i = 0; i < std::llround(3.0 / dt); ++i) {
        settling.step(dt);
        for (const CollisionEvent& event : settling.collisions()) {
            if (event.restitutionApplied) {
                limit = event.time + 2.0 * settleRestitution * event.approachSpeed /
                                         (kGravity * (1.0 - settleRestitution));
            }
        }
    }
    const Real settleFall = std::sqrt(2.0 / kGravity);
    result.push_back(quantity("total bouncing time",
                              settleFall * (1 + settleRestitution) / (1 - settleRestitution), limit,
                              1e-6, "s"));
    return result;
}

/// Post-impact state of a cube landing on one edge (2-D: the edge along z), closed form (V7.2).
struct EdgeImpactAnswer {
    Real velocityX;
    Real velocityY;
    Real spinZ;
};

constexpr Real kEdgeTilt = 20.0 * std::numbers::pi / 180.0;
constexpr Real kEdgeSpeed = 2.0;
constexpr Real kEdgeRestitution = 0.5;

/// Offset of the lowest edge's midpoint from the centre: body corner (-1, -1) turned by the tilt.
Vec3 edgeOffset()
{
    return Vec3(-std::cos(kEdgeTilt) + std::sin(kEdgeTilt), -std::sin(kEdgeTilt) - std::cos(kEdgeTilt), 0);
}

EdgeImpactAnswer edgeImpactClosedForm(Real friction)
{
    // Unit cube 2 x 2 x 2 of mass 1: I = 2/3. Collision matrix entries (V7.1).
    const Real mass = 1.0;
    const Real inertia = 2.0 / 3.0;
    const Vec3 r = edgeOffset();
    const Real a = 1 / mass + r.y * r.y / inertia;
    const Real b = r.x * r.y / inertia;
    const Real c = 1 / mass + r.x * r.x / inertia;
    const Real normalChange = (1 + kEdgeRestitution) * kEdgeSpeed;
    const Real stickingThreshold = std::abs(b) / a;
    Real px = 0.0;
    Real py = 0.0;
    if (friction >= stickingThreshold) {
        py = normalChange / (c - b * b / a);
        px = py * b / a;
    } else {
        py = normalChange / (c - friction * std::abs(b));
        px = std::copysign(friction * py, b);
    }
    return {px / mass, -kEdgeSpeed + py / mass, (r.x * py - r.y * px) / inertia};
}

EdgeImpactAnswer edgeImpactSimulated(Real friction, Real dt)
{
    // No gravity, so the body meets the ground at exactly the speed it was given.
    World world = makeWorld(WorldSettings{.gravity = Vec3(0.0)}, true);
    BodyDef def;
    def.orientation = axisAngle(Vec3(0, 0, 1), kEdgeTilt);
    def.position = Vec3(0, -edgeOffset().y + 0.01, 0);
    def.linearVelocity = Vec3(0, -kEdgeSpeed, 0);
    def.material = {.restitution = kEdgeRestitution, .friction = friction};
    const BodyId id = world.createBody(withFault(def));
    for (int i = 0; i < 1000 && world.collisions().empty(); ++i) {
        world.step(dt);
    }
    const Body& body = world.body(id);
    return {body.linearVelocity.x, body.linearVelocity.y, body.angularVelocity.z};
}

std::vector<Quantity> edgeImpact(Real dt)
{
    const Vec3 r = edgeOffset();
    const Real inertia = 2.0 / 3.0;
    const Real threshold = std::abs(r.x * r.y / inertia) / (1 + r.y * r.y / inertia);
    std::vector<Quantity> result;
    const auto add = [&](const std::string& label, Real friction) {
        const EdgeImpactAnswer exact = edgeImpactClosedForm(friction);
        const EdgeImpactAnswer simulated = edgeImpactSimulated(friction, dt);
        result.push_back(quantity(label + ": vx", exact.velocityX, simulated.velocityX, 1e-9, "m/s"));
        result.push_back(quantity(label + ": vy", exact.velocityY, simulated.velocityY, 1e-9, "m/s"));
        result.push_back(quantity(label + ": wz", exact.spinZ, simulated.spinZ, 1e-9, "rad/s"));
    };
    add("frictionless", 0.0);
    add("sticking (mu = 2 mu*)", 2.0 * threshold);
    add("sliding (mu = mu*/2)", 0.5 * threshold);

    // (V7.3): the smallest mu that leaves the edge without sliding, by bisection on the solver.
    Real sliding = 0.0;
    Real sticking = 1.0;
    for (int halving = 0; halving < 30; ++halving) {
        const Real friction = 0.5 * (sliding + sticking);
        const EdgeImpactAnswer after = edgeImpactSimulated(friction, dt);
        // Sticking: the edge leaves with no sliding, to 5e-6 of the impact speed. Near mu* the
        // sweeps converge ever more slowly; extrapolated (5.14) they reach it within 3e-6 of
        // mu* (plain Gauss-Seidel stopped at its cap 1.3e-3 above).
        const Real tangential = after.velocityX - after.spinZ * r.y;
        (std::abs(tangential) < 5e-6 * kEdgeSpeed ? sticking : sliding) = friction;
    }
    result.push_back(quantity("sticking threshold mu*", threshold, sticking, 3e-5, "1"));
    return result;
}

std::vector<Quantity> slidingToRest(Real dt)
{
    // (V8.1): constant deceleration mu g: time v0 / (mu g), distance v0^2 / (2 mu g).
    const Real speed = 4.0;
    const Real friction = 0.5;
    World world = makeWorld(WorldSettings{}, true);
    const Vec3 direction(std::cos(0.3), 0, std::sin(0.3));
    const BodyId id = world.createBody(withFault(BodyDef{
        .mass = 2.0, .position = Vec3(0, 1, 0), .linearVelocity = speed * direction,
        .material = {.restitution = 0.0, .friction = friction}}));
    Real stopped = -1.0;
    for (long long i = 0; i < std::llround(2.0 / dt); ++i) {
        world.step(dt);
        if (stopped < 0.0 && glm::length(world.body(id).linearVelocity) < 1e-6) {
            stopped = world.time();
        }
    }
    return {quantity("distance", speed * speed / (2 * friction * kGravity),
                     glm::length(world.body(id).position - Vec3(0, 1, 0)), 1e-4, "m"),
            // The stop is seen at the end of the step in which it happens.
            quantity("time to rest", speed / (friction * kGravity), stopped, dt, "s")};
}

/// Whether the 2 x 6 x 2 cuboid, stood on its -y face's edge x = -1 (pivot on the ground) and
/// tilted by `tilt` about z, with spin `spin` about that edge, ends on a face other than -y.
bool tipsOver(Real tilt, Real spin, Real dt)
{
    World world = makeWorld(WorldSettings{.allowSleep = false}, true);
    BodyDef def = handoutCuboid(2.0);
    def.orientation = axisAngle(Vec3(0, 0, 1), tilt);
    const Vec3 pivotOffset = def.orientation * Vec3(-1, -3, 0);
    def.position = Vec3(0, -pivotOffset.y, 0);
    def.angularVelocity = Vec3(0, 0, spin);
    def.linearVelocity = glm::cross(def.angularVelocity, -pivotOffset);
    def.material = {.restitution = 0.0, .friction = 1.0};
    const BodyId id = world.createBody(withFault(def));
    // Long enough for the slowest fall the bisection meets: 10 halvings of a 0.1 rad bracket
    // leave 1e-4 rad from balance, which the growth rate sqrt(m g R / I_edge) = 1.5/s turns into
    // a fall in about 6 s.
    simulate(world, 9.0, dt);
    return faceAlong(world.body(id).orientation, Vec3(0, -1, 0)) != CuboidFace::MinusY;
}

std::vector<Quantity> tipping(Real dt)
{
    // (V9.1): balanced on an edge, it falls over once the centre passes above the edge:
    // tan(theta*) = w / h.
    const Real criticalAngle = std::atan(2.0 / 6.0);
    Real stays = criticalAngle - 0.05;
    Real falls = criticalAngle + 0.05;
    for (int halving = 0; halving < 10; ++halving) {
        const Real tilt = 0.5 * (stays + falls);
        (tipsOver(tilt, 0.0, dt) ? falls : stays) = tilt;
    }
    // (V9.2): standing upright, a spin w about an edge tips it when I_edge w^2 / 2 reaches
    // m g (R - h/2), R the distance from the edge to the centre.
    const Real mass = 2.0;
    const Real reach = std::sqrt(10.0);
    const Real edgeInertia = mass / 12.0 * (4.0 + 36.0) + mass * reach * reach;
    const Real criticalSpin = std::sqrt(2.0 * mass * kGravity * (reach - 3.0) / edgeInertia);
    Real staysSpin = 0.5 * criticalSpin;
    Real fallsSpin = 1.5 * criticalSpin;
    for (int halving = 0; halving < 10; ++halving) {
        const Real spin = 0.5 * (staysSpin + fallsSpin);
        // Upright, spinning towards -x about the edge x = -1 (positive spin about z).
        (tipsOver(0.0, spin, dt) ? fallsSpin : staysSpin) = spin;
    }
    return {quantity("critical spin about the edge", criticalSpin, 0.5 * (staysSpin + fallsSpin),
                     0.01 * criticalSpin, "rad/s"),
            quantity("critical tilt", criticalAngle * 180 / std::numbers::pi,
                     0.5 * (stays + falls) * 180 / std::numbers::pi, 0.05, "deg")};
}

} // namespace

void addContactCases(std::vector<Case>& cases)
{
    cases.push_back({"face-down bounces", "6", 0, bounces});
    cases.push_back({"edge impact", "7", 0, edgeImpact});
    cases.push_back({"sliding to rest", "8", 2, slidingToRest});
    cases.push_back({"tipping", "9", 1, tipping});
}

} // namespace tumble::validation
