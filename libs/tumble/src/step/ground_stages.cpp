// Stages of a body against the ground shared by the default and the handouts' step.
#include "step/ground_stages.hpp"

#include "collision/collide_cuboid_plane.hpp"
#include "dynamics/energy_booking.hpp"
#include "dynamics/integrator.hpp"

namespace tumble {

ContactManifold groundContacts(BodyId id, const Body& body, const StepContext& context)
{
    ContactManifold manifold =
        context.ground ? collideCuboidPlane({body.position, body.orientation},
                                            body.shape.halfExtents(), *context.ground,
                                            context.settings.contactTolerance)
                       : ContactManifold{};
    manifold.body = id;
    return manifold;
}

void integratePositions(Body& body, const Vec3& velocityStart, Real tau, Integrator integrator)
{
    // (2.2): with the velocity changing uniformly over the sub-step the mean velocity is exact;
    // the handout integrator takes the end velocity (semi-implicit Euler, (2.3)).
    const Vec3 mean = integrator == Integrator::Exact ? 0.5 * (velocityStart + body.linearVelocity)
                                                      : body.linearVelocity;
    body.position += tau * mean;
    integrateRotation(body, tau, integrator);
}

void moveFreely(Body& body, Real dt, const WorldSettings& settings)
{
    const Real energyStart = energyOf(body, settings.gravity);
    const Vec3 velocityStart = body.linearVelocity;
    body.linearVelocity += settings.gravity * dt;
    integratePositions(body, velocityStart, dt, settings.integrator);
    bookContact(body, ContactWork{}, energyOf(body, settings.gravity) - energyStart, false);
}

void correctPenetration(Body& body, const std::optional<Plane>& ground)
{
    if (!ground) {
        return;
    }
    const Real lowest =
        lowestVertexHeight({body.position, body.orientation}, body.shape.halfExtents(), *ground);
    if (lowest < 0.0) {
        body.position -= lowest * Plane::normal();
    }
}

void recordContacts(ContactPhase phase, const ContactManifold& contacts, const Body& body,
                    Real time, const WorldSettings& settings, StepEvents& events)
{
    if (settings.recordContacts && contacts.pointCount > 0) {
        events.contactRecords.push_back(ContactRecord{time, phase, body.position, contacts});
    }
}

void recordImpact(const ContactManifold& contacts, const ImpactOutcome& outcome, Real time,
                  StepEvents& events)
{
    CollisionEvent event;
    event.time = time;
    event.manifold = contacts;
    event.approachSpeed = outcome.approachSpeed;
    event.normalImpulse = outcome.normalImpulse;
    event.frictionImpulse = outcome.frictionImpulse;
    event.restitutionApplied = outcome.restitutionApplied;
    event.restitution = outcome.restitution;
    event.kineticEnergyBefore = outcome.kineticEnergyBefore;
    event.kineticEnergyAfter = outcome.kineticEnergyAfter;
    events.collisions.push_back(event);
}

} // namespace tumble
