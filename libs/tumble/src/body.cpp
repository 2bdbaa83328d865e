// Derived quantities of a body: the "update on change" design of handout part 2, task 1.
#include "body_state.hpp"

namespace tumble {

Body makeBody(const BodyDef& def)
{
    Body body;
    body.motion = def.motion;
    body.shape = def.shape;
    body.mass = def.mass;
    body.position = def.position;
    body.orientation = glm::normalize(def.orientation);
    body.linearVelocity = def.linearVelocity;
    body.angularVelocity = def.angularVelocity;
    body.material = def.material;
    body.materialGiven = def.materialGiven;
    refreshMassProperties(body);
    return body;
}

void refreshMassProperties(Body& body)
{
    // a static body is infinitely heavy: no impulse moves it
    if (body.isStatic()) {
        body.invMass = 0.0;
        body.invInertiaBody = Vec3(0.0);
        body.linearVelocity = Vec3(0.0);
        body.angularVelocity = Vec3(0.0);
        refreshWorldInertia(body);
        return;
    }
    body.invMass = 1.0 / body.mass;
    body.invInertiaBody = cuboidInverseInertiaDiagonal(body.mass, body.shape.size);
    refreshWorldInertia(body);
}

void refreshWorldInertia(Body& body)
{
    body.invInertiaWorld = rotateDiagonalTensor(body.rotation(), body.invInertiaBody);
}

void applyImpulseAtOffset(Body& body, const Vec3& impulse, const Vec3& offset)
{
    body.linearVelocity += body.invMass * impulse;
    body.angularVelocity += body.invInertiaWorld * glm::cross(offset, impulse);
}

} // namespace tumble
