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

void updateIslandRest(std::span<const std::uint32_t> bodies, std::span<BodySlot> slots,
                      const StepContext& context, Real dt, StepEvents& events)
{
    const WorldSettings& settings = context.settings;
    bool slow = true;
    for (const std::uint32_t index : bodies) {
        const BodySlot& slot = slots[index];
        slow = slow && slot.touchingGround &&
               glm::length(slot.body.linearVelocity) < settings.sleepLinearSpeed &&
               glm::length(slot.body.angularVelocity) < settings.sleepAngularSpeed;
    }
    bool reachesRest = false;
    for (const std::uint32_t index : bodies) {
        BodySlot& slot = slots[index];
        const Real slowBefore = slot.body.slowTime;
        if (slow && slowBefore == 0.0) {
            slot.slowSince = context.time + dt;
        }
        slot.body.slowTime = slow ? slowBefore + dt : 0.0;
        reachesRest = reachesRest || (slowBefore < settings.sleepTime &&
                                      slot.body.slowTime >= settings.sleepTime);
    }
    if (!reachesRest) {
        return;
    }
    for (const std::uint32_t index : bodies) {
        BodySlot& slot = slots[index];
        Body& body = slot.body;
        events.restEvents.push_back(RestEvent{BodyId{index, slot.generation}, slot.slowSince,
                                              faceAlong(body.orientation, -Plane::normal())});
        if (settings.allowSleep) {
            body.ledger.removedByRest += body.kineticEnergy();
            body.asleep = true;
            body.linearVelocity = Vec3(0.0);
            body.angularVelocity = Vec3(0.0);
        }
    }
}

} // namespace tumble
