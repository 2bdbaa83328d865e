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

/// What a body's kinetic energy depends on besides its velocities: its mass, its body-frame
/// inertia diagonal and its orientation.
struct InertialFrame {
    Quat orientation{1.0, 0.0, 0.0, 0.0};
    Vec3 inertia{0.0};
    Real mass = 0.0;
};

inline InertialFrame inertialFrameOf(const Body& body)
{
    return {body.orientation, body.inertiaBody(), body.mass};
}

/// The kinetic energy a body of that frame has with velocities `linear` and `angular`, J:
/// m |v|^2 / 2 + (I0 w0) . w0 / 2 with w0 = q* w q the spin in the body frame.
Real kineticEnergyWith(const InertialFrame& frame, const Vec3& linear, const Vec3& angular);

/// The kinetic energy `body` would have with velocities `linear` and `angular`, J.
inline Real kineticEnergyWith(const Body& body, const Vec3& linear, const Vec3& angular)
{
    return kineticEnergyWith(inertialFrameOf(body), linear, angular);
}

/// Work of an island's contact impulses in one stage, J: the totals of its points' normal and
/// friction work (8.2).
struct IslandWork {
    Real normal = 0.0;
    Real friction = 0.0;
};

/// The points' work summed in fixed groups of consecutive points, the groups spread over
/// `threads` and added in order, so the total is the same for any number of threads.
IslandWork sumPointWork(std::span<const ContactConstraint> constraints, int threads = 1);

/// (8.4): the island's total work of the normal and of the friction impulses, shared among its
/// bodies in proportion to their kinetic energy before the stage (their mass when all are at
/// rest); what a body received beyond its share, `bodyWork` (the change of its kinetic energy
/// the impulses made) less the share, is exchanged, and the exchanges sum to zero.
std::vector<ContactWork> shareIslandWork(const IslandWork& total, std::span<const Real> bodyWork,
                                         std::span<const Real> kineticBefore,
                                         std::span<const SolverBody> bodies);

/// shareIslandWork for one body, given the island's kinetic energy before the stage
/// (`kinetic`) and its mass (`mass`), and the body's `bodyWork`, kinetic energy before the stage
/// and inverse mass.
ContactWork shareOfIslandWork(const IslandWork& total, Real kinetic, Real mass, Real bodyWork,
                              Real kineticBefore, Real invMass);

} // namespace tumble
