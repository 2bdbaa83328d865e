// Keeping a Body's derived quantities (inverse mass and inertia) consistent with its state.
#pragma once

#include "tumble/body.hpp"

namespace tumble {

/// A Body from its definition, with every derived quantity computed.
Body makeBody(const BodyDef& def);

/// After a change of mass or size: inverse mass, body-frame and world-frame inverse inertia.
void refreshMassProperties(Body& body);

/// After a change of orientation: R I0^-1 R^T (docs/physics/01-inertia.md, (1.3)).
void refreshWorldInertia(Body& body);

/// Applies an impulse at an offset from the centre of mass (docs/physics/03-impulses.md, (3.1),
/// (3.2)): dv = J/m, dw = I^-1 (r x J).
void applyImpulseAtOffset(Body& body, const Vec3& impulse, const Vec3& offset);

} // namespace tumble
