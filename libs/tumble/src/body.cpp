// Derived quantities of a body: the "update on change" design of handout part 2, task 1.
#include "body_state.hpp"

namespace tumble {

Body makeBody(const BodyDef& def)
{
    Body body;
    body.shape = def.shape;
    body.mass = def.mass;
    body.position = def.position;
    body.orientation = glm::normalize(def.orientation);
    body.linearVelocity = def.linearVelocity;
    body.angularVelocity = def.angularVelocity;
    body.material = def.material;
    refreshMassProperties(body);
    return body;
}

void refreshMassProperties(Body& body)
{
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
