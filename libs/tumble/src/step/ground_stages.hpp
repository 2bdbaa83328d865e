// The stages a body goes through against the ground that both the default step and the
// handouts' step use: detection, free motion, position integration, push-out and reporting.
#pragma once

#include "dynamics/contact_solver.hpp"
#include "step/step_context.hpp"
#include "step/step_events.hpp"
#include "tumble/body.hpp"
#include "tumble/contact.hpp"

namespace tumble {

/// The vertices of the body touching the ground (within the contact tolerance) at its pose,
/// (4.1)-(4.2); an empty manifold without a ground.
ContactManifold groundContacts(BodyId id, const Body& body, const StepContext& context);

/// Translation and rotation over tau: the mean of the start and end velocities (2.2), or the end
/// velocity for the handout integrator (2.3); the rotation by (2.7) or (2.8).
void integratePositions(Body& body, const Vec3& velocityStart, Real tau,
                        Integrator integrator);

/// Gravity and integration over dt with nothing touching, booked to the energy ledger.
void moveFreely(Body& body, Real dt, const WorldSettings& settings);

/// (4.5): a pure translation along the normal that lifts the lowest vertex onto the ground when
/// it is below; velocities are untouched, so no kinetic energy is added.
void correctPenetration(Body& body, const std::optional<Plane>& ground);

/// Keeps a ContactRecord of a solve when the settings ask for the contact ledger.
void recordContacts(ContactPhase phase, const ContactManifold& contacts, const Body& body,
                    Real time, const WorldSettings& settings, StepEvents& events);

/// Reports an impact.
void recordImpact(const ContactManifold& contacts, const ImpactOutcome& outcome, Real time,
                  StepEvents& events);

} // namespace tumble
