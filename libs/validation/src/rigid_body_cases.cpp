// Cases without contact: inertia, impulses, free fall, the symmetric top, the intermediate axis
// (docs/validation.md, sections 1-5).
#include "case_support.hpp"

#include "tumble/impulse_target.hpp"

#include <cmath>
#include <numbers>

namespace tumble::validation {
namespace {

std::vector<Quantity> inverseInertia(Real)
{
    // (V1.1): R diag(0.15, 0.75, 0.15) R^T with R = rot_z(30 deg), and diag(0.3, 1.5, 0.3).
    World world = makeWorld(WorldSettings{.gravity = Vec3(0.0)}, false);
    BodyDef rotated = handoutCuboid(2.0);
    rotated.orientation = axisAngle(Vec3(0, 0, 1), std::numbers::pi / 6.0);
    const Mat3 inverse = world.body(world.createBody(rotated)).invInertiaWorld;
    const BodyId light = world.createBody(handoutCuboid(2.0));
    world.setMass(light, 1.0);
    const Vec3 lightDiagonal = world.body(light).invInertiaBody;
    const Real tolerance = 1e-12;
    const char* unit = "1/(kg m^2)";
    return {quantity("m=2, rot 30: xx", 0.3, inverse[0][0], tolerance, unit),
            quantity("m=2, rot 30: xy", -0.15 * std::sqrt(3.0), inverse[1][0], tolerance, unit),
            quantity("m=2, rot 30: yy", 0.6, inverse[1][1], tolerance, unit),
            quantity("m=2, rot 30: zz", 0.15, inverse[2][2], tolerance, unit),
            quantity("m=1: xx", 0.3, lightDiagonal.x, tolerance, unit),
            quantity("m=1: yy", 1.5, lightDiagonal.y, tolerance, unit)};
}

struct ImpulseExperiment {
    const char* name;
    Real mass;
    Vec3 velocity;
    Vec3 angularVelocity;
    Vec3 targetVelocity;
    Vec3 targetAngularVelocity;
};

std::vector<Quantity> handoutImpulses(Real dt)
{
    // (V2.1): after 2 s of free flight the solved impulse reaches the target exactly.
    const ImpulseExperiment experiments[] = {
        {"left", 1.0, Vec3(0), Vec3(0), Vec3(-1, 0, 0), Vec3(0)},
        {"left+spin", 1.0, Vec3(0), Vec3(0), Vec3(-1, 0, 0), Vec3(0, 0, 0.5)},
        {"stop", 1.0, Vec3(3, 0, 0), Vec3(0), Vec3(0), Vec3(0)},
        {"reverse", 1.0, Vec3(3, 0, 0), Vec3(0), Vec3(-3, 0, 0), Vec3(0)},
        {"stop+spin", 1.0, Vec3(3, 0, 0), Vec3(0), Vec3(0), Vec3(0, 0, -0.5)},
        {"stop all", 1.0, Vec3(3, 0, 0), Vec3(0, 0, 1), Vec3(0), Vec3(0)},
        {"part 3 task 1", 2.0, Vec3(2, 0, 0), Vec3(0), Vec3(0), Vec3(0, 0, -0.6)},
    };
    std::vector<Quantity> result;
    for (const ImpulseExperiment& experiment : experiments) {
        World world = makeWorld(WorldSettings{.gravity = Vec3(0.0)}, false);
        BodyDef def = handoutCuboid(experiment.mass);
        def.linearVelocity = experiment.velocity;
        def.angularVelocity = experiment.angularVelocity;
        const BodyId id = world.createBody(def);
        simulate(world, 2.0, dt);
        const Body& body = world.body(id);
        const ImpulseTarget solved = solveImpulseTarget(body, experiment.targetVelocity,
                                                        experiment.targetAngularVelocity);
        world.applyImpulse(id, solved.impulse, body.position + solved.offset);
        const Real miss = glm::length(body.linearVelocity - experiment.targetVelocity) +
                          glm::length(body.angularVelocity - experiment.targetAngularVelocity);
        result.push_back(quantity(std::string(experiment.name) + ": |v-v*|+|w-w*|", 0.0,
                                  solved.status == ImpulseTargetStatus::Reached ? miss : 1.0,
                                  1e-12, "SI"));
    }
    return result;
}

std::vector<Quantity> freeFall(Real dt, Integrator integrator)
{
    // (V3.1): y(t) = y0 - g t^2 / 2, v(t) = -g t.
    World world = makeWorld(WorldSettings{.integrator = integrator}, false);
    const BodyId id = world.createBody(BodyDef{.position = Vec3(0, 10, 0)});
    simulate(world, 1.0, dt);
    const Body& body = world.body(id);
    // The exact integrator is exact; semi-implicit Euler lags by g t dt / 2 (V3.2).
    const Real tolerance = integrator == Integrator::Exact ? 1e-9 : 0.03;
    return {quantity("height at t = 1 s", 10.0 - 0.5 * kGravity, body.position.y, tolerance, "m"),
            quantity("velocity at t = 1 s", -kGravity, body.linearVelocity.y, 1e-9, "m/s")};
}

std::vector<Quantity> symmetricTop(Real dt)
{
    // (V4.1)-(V4.3): 2 x 6 x 2, m = 2, w0 = (0.1, 0.1, 0.1), no gravity, 100 s.
    World world = makeWorld(WorldSettings{.gravity = Vec3(0.0)}, false);
    BodyDef def = handoutCuboid(2.0);
    def.angularVelocity = Vec3(0.1);
    const BodyId id = world.createBody(def);
    const Body& body = world.body(id);
    const Vec3 momentum0 = body.angularMomentum();
    const Real energy0 = body.kineticEnergy();
    const Vec3 inertia = body.inertiaBody();
    Vec3 helper1;
    Vec3 helper2;
    orthonormalBasis(glm::normalize(momentum0), helper1, helper2);
    const auto bodyPhase = [&] {
        const Vec3 w = glm::conjugate(body.orientation) * body.angularVelocity;
        return -std::atan2(w.z, w.x);
    };
    const auto spacePhase = [&] {
        const Vec3 axis = body.orientation * Vec3(0, 1, 0);
        return std::atan2(glm::dot(axis, helper2), glm::dot(axis, helper1));
    };
    Real bodyAngle = 0.0;
    Real spaceAngle = 0.0;
    Real previousBody = bodyPhase();
    Real previousSpace = spacePhase();
    Real momentumDrift = 0.0;
    Real energyDrift = 0.0;
    const Real duration = 100.0;
    for (long long i = 0; i < std::llround(duration / dt); ++i) {
        world.step(dt);
        bodyAngle += std::remainder(bodyPhase() - previousBody, 2 * std::numbers::pi);
        spaceAngle += std::remainder(spacePhase() - previousSpace, 2 * std::numbers::pi);
        previousBody = bodyPhase();
        previousSpace = spacePhase();
        momentumDrift = std::max(momentumDrift,
                                 glm::length(body.angularMomentum() - momentum0) / glm::length(momentum0));
        energyDrift = std::max(energyDrift, std::abs(body.kineticEnergy() / energy0 - 1.0));
    }
    return {quantity("body-frame precession", (inertia.y - inertia.x) / inertia.x * 0.1,
                     bodyAngle / duration, 1e-6, "rad/s"),
            quantity("space-frame precession", glm::length(momentum0) / inertia.x,
                     spaceAngle / duration, 1e-6, "rad/s"),
            quantity("max |L - L0| / |L0|", 0.0, momentumDrift, 1e-9, "1"),
            quantity("max |K - K0| / K0", 0.0, energyDrift, 1e-6, "1")};
}

std::vector<Quantity> intermediateAxis(Real dt)
{
    // (V5.1)-(V5.3): a 1 x 2 x 3 box spun near its intermediate axis y flips with the half
    // period 2 K(k) / lambda of the Jacobi functions (Landau & Lifshitz, section 37).
    World world = makeWorld(WorldSettings{.gravity = Vec3(0.0)}, false);
    const Vec3 spin(0.01, 4.0, 0.01);
    const BodyId id = world.createBody(BodyDef{.shape = {.size = Vec3(1, 2, 3)}, .angularVelocity = spin});
    const Body& body = world.body(id);
    const Vec3 inertia = body.inertiaBody();
    // Landau's labels: I1 < I2 < I3 are z, y, x here.
    const Real i1 = inertia.z;
    const Real i2 = inertia.y;
    const Real i3 = inertia.x;
    const Real energy2 = glm::dot(spin, inertia * spin); // 2E
    const Real momentum2 = glm::dot(inertia * spin, inertia * spin); // M^2
    Real lambda = 0.0;
    Real modulus2 = 0.0;
    if (momentum2 > energy2 * i2) {
        lambda = std::sqrt((i3 - i2) * (momentum2 - energy2 * i1) / (i1 * i2 * i3));
        modulus2 = (i2 - i1) * (energy2 * i3 - momentum2) / ((i3 - i2) * (momentum2 - energy2 * i1));
    } else {
        lambda = std::sqrt((i2 - i1) * (energy2 * i3 - momentum2) / (i1 * i2 * i3));
        modulus2 = (i3 - i2) * (momentum2 - energy2 * i1) / ((i2 - i1) * (energy2 * i3 - momentum2));
    }
    const Real halfPeriod = 2.0 * std::comp_ellint_1(std::sqrt(modulus2)) / lambda;

    // Times at which the body-frame w_y changes sign, by linear interpolation between steps.
    std::vector<Real> flips;
    Real previous = spin.y;
    for (long long i = 0; i < std::llround(6.0 * halfPeriod / dt); ++i) {
        world.step(dt);
        const Real current = (glm::conjugate(body.orientation) * body.angularVelocity).y;
        if (current * previous < 0.0) {
            flips.push_back(world.time() - dt * current / (current - previous));
        }
        previous = current;
    }
    const Real measured = flips.size() >= 2
                              ? (flips.back() - flips.front()) / static_cast<Real>(flips.size() - 1)
                              : 0.0;
    return {quantity("time between flips", halfPeriod, measured, 1e-3 * halfPeriod, "s")};
}

} // namespace

void addRigidBodyCases(std::vector<Case>& cases)
{
    cases.push_back({"inverse inertia", "1", 0, inverseInertia});
    cases.push_back({"handout impulses", "2", 0, handoutImpulses});
    cases.push_back({"free fall", "3", 0, [](Real dt) { return freeFall(dt, Integrator::Exact); }});
    cases.push_back({"free fall, handout integrator", "3", 1,
                     [](Real dt) { return freeFall(dt, Integrator::Handout); }});
    cases.push_back({"symmetric top", "4", 0, symmetricTop});
    cases.push_back({"intermediate axis", "5", 2, intermediateAxis});
}

} // namespace tumble::validation
