// Booking each stage's change of a body's energy under one heading of its ledger
// (docs/physics/08-energy-ledger.md, (8.1)-(8.3)).
#pragma once

#include "dynamics/contact_constraint.hpp"
#include "dynamics/contact_solver.hpp"
#include "tumble/body.hpp"

#include <span>
#include <vector>

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

/// (8.4): the island's total work of the normal and of the friction impulses, shared among its
/// bodies in proportion to their kinetic energy before the stage (their mass when all are at
/// rest); what a body received beyond its share is exchanged, and the exchanges sum to zero.
std::vector<ContactWork> shareIslandWork(std::span<const SolverBody> bodies,
                                         std::span<const Real> kineticBefore);

} // namespace tumble
