// Rest detection per body (docs/physics/07-rest.md).
#include "dynamics/rest.hpp"

#include <glm/geometric.hpp>

namespace tumble {

void updateRest(BodyId id, BodySlot& slot, const StepContext& context, Real dt,
                StepEvents& events)
{
    const WorldSettings& settings = context.settings;
    Body& body = slot.body;
    const bool slow = slot.touchingGround &&
                      glm::length(body.linearVelocity) < settings.sleepLinearSpeed &&
                      glm::length(body.angularVelocity) < settings.sleepAngularSpeed;
    const Real slowBefore = body.slowTime;
    if (slow && slowBefore == 0.0) {
        slot.slowSince = context.time + dt;
    }
    body.slowTime = slow ? body.slowTime + dt : 0.0;
    if (slowBefore >= settings.sleepTime || body.slowTime < settings.sleepTime) {
        return;
    }
    events.restEvents.push_back(
        RestEvent{id, slot.slowSince, faceAlong(body.orientation, -Plane::normal())});
    if (settings.allowSleep) {
        body.ledger.removedByRest += body.kineticEnergy();
        body.asleep = true;
        body.linearVelocity = Vec3(0.0);
        body.angularVelocity = Vec3(0.0);
    }
}

} // namespace tumble
