// The case registry, the installed fault and the observed order of convergence.
#include "tumble/validation/validation.hpp"

#include "case_support.hpp"

#include <cmath>

namespace tumble::validation {
namespace {

Fault& installedFault()
{
    static Fault fault;
    return fault;
}

} // namespace

void setFaultForTesting(const Fault& fault) { installedFault() = fault; }

World makeWorld(WorldSettings settings, bool withGround)
{
    if (installedFault().integrator) {
        settings.integrator = *installedFault().integrator;
    }
    World world(settings);
    if (withGround) {
        world.setGround(Plane{});
    }
    return world;
}

BodyDef withFault(BodyDef def)
{
    def.material.restitution *= installedFault().restitutionScale;
    return def;
}

BodyDef handoutCuboid(Real mass)
{
    BodyDef def;
    def.shape.size = Vec3(2.0, 6.0, 2.0);
    def.mass = mass;
    return def;
}

void simulate(World& world, Real seconds, Real dt)
{
    const long long steps = std::llround(seconds / dt);
    for (long long i = 0; i < steps; ++i) {
        world.step(dt);
    }
}

Quantity quantity(std::string name, Real exact, Real value, Real tolerance, std::string unit)
{
    return Quantity{std::move(name), exact, value, tolerance, std::move(unit)};
}

std::vector<Case> cases()
{
    std::vector<Case> all;
    addRigidBodyCases(all);
    addContactCases(all);
    addTouchingCases(all);
    return all;
}

std::vector<Real> convergenceSteps()
{
    return {1.0 / 60.0, 1.0 / 120.0, 1.0 / 240.0, 1.0 / 480.0, 1.0 / 960.0};
}

std::optional<Real> observedOrder(const std::vector<Real>& steps, const std::vector<Real>& errors,
                                  Real floor)
{
    // Fit log e = p log dt + c by least squares over the errors above the rounding floor.
    std::vector<Real> x;
    std::vector<Real> y;
    for (std::size_t i = 0; i < steps.size() && i < errors.size(); ++i) {
        if (errors[i] > floor) {
            x.push_back(std::log(steps[i]));
            y.push_back(std::log(errors[i]));
        }
    }
    if (x.size() < 2) {
        return std::nullopt;
    }
    const Real n = static_cast<Real>(x.size());
    Real sumX = 0.0;
    Real sumY = 0.0;
    Real sumXX = 0.0;
    Real sumXY = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sumX += x[i];
        sumY += y[i];
        sumXX += x[i] * x[i];
        sumXY += x[i] * y[i];
    }
    return (n * sumXY - sumX * sumY) / (n * sumXX - sumX * sumX);
}

} // namespace tumble::validation
