// The handouts' order of a step: move, detect, lift out, one impulse at the average point.
#include "step/handout_step.hpp"

#include "dynamics/contact_solver.hpp"
#include "dynamics/energy_booking.hpp"
#include "step/ground_stages.hpp"

#include <glm/geometric.hpp>

namespace tumble {

void advanceHandoutStep(BodyId id, BodySlot& slot, const StepContext& context, Real dt,
                        StepEvents& events)
{
    const WorldSettings& settings = context.settings;
    Body& body = slot.body;
    moveFreely(body, dt, settings);
    ContactManifold contacts = groundContacts(id, body, context);
    const bool wasTouching = slot.touchingGround;
    slot.touchingGround = contacts.pointCount > 0;
    if (contacts.pointCount == 0) {
        return;
    }
    // move the body up so its lowest vertex lies on the plane (handout part 2, task 3); the
    // lift's rounding at a great depth is left to the push-out (4.5)
    const Real lift = contacts.maxPenetration();
    const Real energyBeforeLift = energyOf(body, settings.gravity);
    body.position += lift * contacts.normal;
    correctPenetration(body, context.ground);
    bookCorrection(body, energyBeforeLift, settings.gravity);
    for (int i = 0; i < contacts.pointCount; ++i) {
        contacts.points[i].position += lift * contacts.normal;
    }
    // one impulse at the average touching vertex (5.7)
    const ContactSolveSettings solveSettings{settings.restitutionThreshold,
                                             settings.solverIterations};
    const Real energyBeforeImpulse = energyOf(body, settings.gravity);
    const ImpactOutcome outcome = resolveAverageContact(body, contacts, solveSettings);
    bookContact(body, outcome.work, energyOf(body, settings.gravity) - energyBeforeImpulse, true);
    const Real endTime = context.time + dt;
    recordContacts(ContactPhase::Average, contacts, body, endTime, settings, events);
    // a resting body gains |g| dt of approach every step; only a real impact is reported
    const Real restingApproach = glm::length(settings.gravity) * dt;
    if (outcome.approachSpeed > 0.0 &&
        (!wasTouching || outcome.approachSpeed > settings.restitutionThreshold + restingApproach)) {
        recordImpact(contacts, outcome, endTime, events);
    }
}

} // namespace tumble
