// Energy booking per stage (docs/physics/08-energy-ledger.md).
#include "dynamics/energy_booking.hpp"

#include "parallel_for.hpp"

#include <algorithm>

namespace tumble {

namespace {

/// The points of one group of sumPointWork; a fixed size, so the grouping does not depend on
/// the threads.
constexpr std::size_t kPointsPerWorkGroup = 4096;

} // namespace

void bookContact(Body& body, const ContactWork& work, Real energyChange, bool impact)
{
    const Real contactWork = work.normal + work.friction;
    body.ledger.removedByNormal -= work.normal;
    body.ledger.removedByFriction -= work.friction;
    body.ledger.exchanged += work.exchanged;
    body.ledger.removedByIntegration -= energyChange - contactWork - work.exchanged;
    if (impact) {
        body.ledger.impactWorkLastStep += contactWork;
    }
}

Real bookCorrection(Body& body, Real energyBefore, const Vec3& gravity)
{
    const Real energyAfter = energyOf(body, gravity);
    body.ledger.removedByCorrection += energyBefore - energyAfter;
    return energyAfter;
}

Real kineticEnergyWith(const InertialFrame& frame, const Vec3& linear, const Vec3& angular)
{
    const Vec3 bodySpin = glm::conjugate(frame.orientation) * angular;
    return 0.5 * frame.mass * lengthSquared(linear) +
           0.5 * glm::dot(frame.inertia * bodySpin, bodySpin);
}

IslandWork sumPointWork(std::span<const ContactConstraint> constraints, int threads)
{
    const std::size_t groups = (constraints.size() + kPointsPerWorkGroup - 1) / kPointsPerWorkGroup;
    std::vector<IslandWork> groupWork(groups);
    parallelFor(groups, threads, [&](std::size_t g) {
        const std::size_t end = std::min(constraints.size(), (g + 1) * kPointsPerWorkGroup);
        for (std::size_t k = g * kPointsPerWorkGroup; k < end; ++k) {
            groupWork[g].normal += constraints[k].normalWork;
            groupWork[g].friction += constraints[k].frictionWork;
        }
    });
    IslandWork total;
    for (const IslandWork& work : groupWork) {
        total.normal += work.normal;
        total.friction += work.friction;
    }
    return total;
}

std::vector<ContactWork> shareIslandWork(const IslandWork& total, std::span<const Real> bodyWork,
                                         std::span<const Real> kineticBefore,
                                         std::span<const SolverBody> bodies)
{
    const std::size_t count = kineticBefore.size();
    Real kinetic = 0.0;
    Real mass = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        kinetic += kineticBefore[i];
        mass += 1.0 / bodies[i].invMass;
    }
    std::vector<ContactWork> work(count);
    for (std::size_t i = 0; i < count; ++i) {
        work[i] = shareOfIslandWork(total, kinetic, mass, bodyWork[i], kineticBefore[i],
                                    bodies[i].invMass);
    }
    return work;
}

ContactWork shareOfIslandWork(const IslandWork& total, Real kinetic, Real mass, Real bodyWork,
                              Real kineticBefore, Real invMass)
{
    const Real share = kinetic > 0.0 ? kineticBefore / kinetic : (1.0 / invMass) / mass;
    ContactWork work;
    work.normal = share * total.normal;
    work.friction = share * total.friction;
    work.exchanged = bodyWork - work.normal - work.friction;
    return work;
}

} // namespace tumble
