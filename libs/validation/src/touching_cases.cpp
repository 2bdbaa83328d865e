// Cases of bodies that touch each other or a tilted plane: head-on impacts, a box on a slope
// (sliding, holding, tipping), a box sliding on a box held by the ground (docs/validation.md,
// sections 12-14).
#include "case_support.hpp"

#include <cmath>
#include <numbers>

namespace tumble::validation {
namespace {

constexpr Real kDegree = std::numbers::pi / 180.0;

std::vector<Quantity> headOnImpacts(Real dt)
{
    // (V12.1): v_A' = (m_A v_A + m_B v_B - m_B e (v_A - v_B)) / (m_A + m_B), and B's by symmetry
    std::vector<Quantity> result;
    struct Pair {
        Real massA;
        Real massB;
        Real restitution;
    };
    for (const Pair pair : {Pair{1.0, 1.0, 1.0}, Pair{1.0, 3.0, 0.5}, Pair{1.0, 100.0, 0.8}}) {
        World world = makeWorld(WorldSettings{.gravity = Vec3(0.0), .allowSleep = false}, false);
        const Material material{.restitution = pair.restitution, .friction = 0.0};
        const BodyId a = world.createBody(withFault(BodyDef{.shape = Cuboid{Vec3(1.0)},
                                                            .mass = pair.massA,
                                                            .position = Vec3(-1.0, 0.0, 0.0),
                                                            .linearVelocity = Vec3(2.0, 0, 0),
                                                            .material = material}));
        const BodyId b = world.createBody(withFault(BodyDef{.shape = Cuboid{Vec3(1.0)},
                                                            .mass = pair.massB,
                                                            .position = Vec3(1.0, 0.0, 0.0),
                                                            .linearVelocity = Vec3(-1.0, 0, 0),
                                                            .material = material}));
        simulate(world, 1.0, dt);
        const Real total = pair.massA + pair.massB;
        const Real momentum = 2.0 * pair.massA - pair.massB;
        const std::string label = "m " + std::to_string(static_cast<int>(pair.massA)) + ":" +
                                  std::to_string(static_cast<int>(pair.massB));
        result.push_back(quantity(label + " v_A'",
                                  (momentum - pair.massB * pair.restitution * 3.0) / total,
                                  world.body(a).linearVelocity.x, 1e-9, "m/s"));
        result.push_back(quantity(label + " v_B'",
                                  (momentum + pair.massA * pair.restitution * 3.0) / total,
                                  world.body(b).linearVelocity.x, 1e-9, "m/s"));
    }
    return result;
}

/// A box `width` wide and deep and `height` tall resting on a plane through the origin tilted by
/// `degrees` about z, and the plane's downhill direction.
struct Slope {
    World world;
    BodyId box;
    Vec3 downhill;
};

Slope makeSlope(Real degrees, Real friction, Real width, Real height)
{
    const Real angle = degrees * kDegree;
    const Vec3 normal(-std::sin(angle), std::cos(angle), 0.0);
    World world = makeWorld(WorldSettings{.allowSleep = false}, false);
    world.addPlane(StaticPlane{.point = Vec3(0.0), .normal = normal});
    const BodyId box = world.createBody(
        withFault(BodyDef{.shape = Cuboid{Vec3(width, height, width)},
                          .position = 0.5 * height * normal,
                          .orientation = axisAngle(Vec3(0, 0, 1), angle),
                          .material = Material{.restitution = 0.0, .friction = friction}}));
    return Slope{std::move(world), box, Vec3(-std::cos(angle), -std::sin(angle), 0.0)};
}

std::vector<Quantity> slope(Real dt)
{
    std::vector<Quantity> result;
    // (V13.1): sliding at 30 degrees with mu = 0.3, d = g (sin t - mu cos t) T^2 / 2 at T = 2 s
    Slope sliding = makeSlope(30.0, 0.3, 1.0, 1.0);
    const Vec3 start = sliding.world.body(sliding.box).position;
    simulate(sliding.world, 2.0, dt);
    const Real angle = 30.0 * kDegree;
    result.push_back(quantity("slide in 2 s",
                              0.5 * kGravity * (std::sin(angle) - 0.3 * std::cos(angle)) * 4.0,
                              glm::dot(sliding.world.body(sliding.box).position - start,
                                       sliding.downhill),
                              1e-4, "m"));
    // (V13.2): held at 20 degrees by mu = 0.37 > tan 20 = 0.364
    Slope holding = makeSlope(20.0, 0.37, 1.0, 1.0);
    const Vec3 rest = holding.world.body(holding.box).position;
    simulate(holding.world, 2.0, dt);
    result.push_back(quantity("drift when held", 0.0,
                              glm::length(holding.world.body(holding.box).position - rest), 1e-6,
                              "m"));
    // (V13.3): a 0.5 x 1.5 box on a rough slope tips once tan t > w / h; bisected over
    // t* +- 2 degrees, 6 halvings, each run 3 s
    Real low = std::atan(1.0 / 3.0) / kDegree - 2.0;
    Real high = low + 4.0;
    for (int halving = 0; halving < 6; ++halving) {
        const Real middle = 0.5 * (low + high);
        Slope tipping = makeSlope(middle, 1.0, 0.5, 1.5);
        const Quat upright = tipping.world.body(tipping.box).orientation;
        simulate(tipping.world, 3.0, dt);
        const bool tipped =
            std::abs(glm::dot(tipping.world.body(tipping.box).orientation, upright)) <
            std::cos(5.0 * kDegree);
        (tipped ? high : low) = middle;
    }
    result.push_back(quantity("tipping angle", std::atan(1.0 / 3.0) / kDegree, 0.5 * (low + high),
                              0.1, "deg"));
    return result;
}

std::vector<Quantity> boxOnBox(Real dt)
{
    // (V14.1): a 1 m cube sliding at 2 m/s on a 2 m box that rests on the ground, mu = 0.4 for
    // both (so 0.4 between them, (11.7)); the lower box is held (0.4 (m1 + m2) g > 0.4 m2 g) and
    // the upper stops after v^2 / (2 mu g) in v / (mu g)
    World world = makeWorld(WorldSettings{.allowSleep = false}, true);
    const Material material{.restitution = 0.0, .friction = 0.4};
    const BodyId lower = world.createBody(withFault(BodyDef{
        .shape = Cuboid{Vec3(4.0, 2.0, 2.0)}, .position = Vec3(0.0, 1.0, 0.0), .material = material}));
    const BodyId upper = world.createBody(withFault(BodyDef{.shape = Cuboid{Vec3(1.0)},
                                                            .position = Vec3(-1.0, 2.5, 0.0),
                                                            .linearVelocity = Vec3(2.0, 0, 0),
                                                            .material = material}));
    simulate(world, 1.0, dt);
    std::vector<Quantity> result;
    result.push_back(quantity("slide distance", 4.0 / (2.0 * 0.4 * kGravity),
                              world.body(upper).position.x + 1.0, 2e-4, "m"));
    result.push_back(quantity("lower box drift", 0.0,
                              glm::length(world.body(lower).position - Vec3(0.0, 1.0, 0.0)), 1e-6,
                              "m"));
    return result;
}

} // namespace

void addTouchingCases(std::vector<Case>& cases)
{
    cases.push_back({"head-on impacts", "12", 0, headOnImpacts});
    cases.push_back({"box on a slope", "13", 0, slope});
    cases.push_back({"box sliding on a box", "14", 2, boxOnBox});
}

} // namespace tumble::validation
