// EnergyLedger: where a body's mechanical energy went since it was created
// (docs/physics/08-energy-ledger.md).
#pragma once

#include "tumble/math.hpp"

namespace tumble {

/// Running totals, J. At any time kinetic + potential + removed() - added - exchanged = initial,
/// to rounding:
/// every change of the body's energy is booked under exactly one heading.
struct EnergyLedger {
    /// Kinetic plus potential energy when the body was created.
    Real initial = 0.0;
    /// Minus the work of the normal contact impulses (restitution below 1, resting contact).
    Real removedByNormal = 0.0;
    /// Minus the work of the friction impulses.
    Real removedByFriction = 0.0;
    /// Potential energy taken away by moving the body out of (or onto) the ground.
    Real removedByCorrection = 0.0;
    /// Energy lost (positive) or gained (negative) by the time integration itself.
    Real removedByIntegration = 0.0;
    /// Kinetic energy set to zero when the body was put to sleep at rest.
    Real removedByRest = 0.0;
    /// Energy received from other bodies through contact impulses (negative: given to them); the
    /// exchanges of the bodies of a contact sum to zero (docs/physics/08-energy-ledger.md, (8.4)).
    Real exchanged = 0.0;
    /// Energy added by applyImpulse and by the setters (velocity, pose, mass, size, gravity).
    Real added = 0.0;
    /// Work of the impact impulses during the last step; positive means the impact solver added
    /// energy, which it must never do. (Resting contact is left out: there the split of a
    /// sub-step's energy change between the contact force and gravity is itself only first-order
    /// accurate, see docs/physics/08-energy-ledger.md.)
    Real impactWorkLastStep = 0.0;

    /// kinetic + potential + removed() - added - exchanged - initial: zero to rounding.
    [[nodiscard]] Real imbalance(Real kineticPlusPotential) const
    {
        return kineticPlusPotential + removed() - added - exchanged - initial;
    }

    [[nodiscard]] Real removed() const
    {
        return removedByNormal + removedByFriction + removedByCorrection + removedByIntegration +
               removedByRest;
    }
};

} // namespace tumble
