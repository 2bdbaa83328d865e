// Energy booking per stage (docs/physics/08-energy-ledger.md).
#include "dynamics/energy_booking.hpp"

namespace tumble {

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

std::vector<ContactWork> shareIslandWork(std::span<const SolverBody> bodies,
                                         std::span<const Real> kineticBefore)
{
    const std::size_t count = kineticBefore.size();
    Real normal = 0.0;
    Real friction = 0.0;
    Real kinetic = 0.0;
    Real mass = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        normal += bodies[i].normalWork;
        friction += bodies[i].frictionWork;
        kinetic += kineticBefore[i];
        mass += 1.0 / bodies[i].invMass;
    }
    std::vector<ContactWork> work(count);
    for (std::size_t i = 0; i < count; ++i) {
        const Real share = kinetic > 0.0 ? kineticBefore[i] / kinetic
                                         : (1.0 / bodies[i].invMass) / mass;
        work[i].normal = share * normal;
        work[i].friction = share * friction;
        work[i].exchanged =
            bodies[i].normalWork + bodies[i].frictionWork - work[i].normal - work[i].friction;
    }
    return work;
}

} // namespace tumble
