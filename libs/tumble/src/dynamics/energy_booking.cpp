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

} // namespace tumble
