// Booking each stage's change of a body's energy under one heading of its ledger
// (docs/physics/08-energy-ledger.md, (8.1)-(8.3)).
#pragma once

#include "dynamics/contact_solver.hpp"
#include "tumble/body.hpp"

namespace tumble {

/// Kinetic plus potential energy of a body in the gravity field, J.
inline Real energyOf(const Body& body, const Vec3& gravity)
{
    return body.kineticEnergy() + body.potentialEnergy(gravity);
}

/// (8.3): the contact impulses' work is booked to them; whatever else changed the energy in the
/// same stage (gravity over a sub-step, the rotation split, rounding) is the integrator's. An
/// impact's work is also kept for the step's check that impacts never add energy.
void bookContact(Body& body, const ContactWork& work, Real energyChange, bool impact);

/// Books the energy a position correction changed since `energyBefore` and returns the body's
/// energy after it.
Real bookCorrection(Body& body, Real energyBefore, const Vec3& gravity);

} // namespace tumble
