// Material: how a body's surface meets the ground (restitution and Coulomb friction).
#pragma once

#include "tumble/math.hpp"

#include <optional>

namespace tumble {

/// Surface properties of a body against the ground.
struct Material {
    /// Coefficient of restitution ("elasticity" in the handouts and scenario files), in [0, 1].
    /// Default 0.6, the handouts' realistic value.
    Real restitution = 0.6;
    /// Kinetic (sliding) Coulomb friction coefficient, >= 0; 0 is frictionless. Default 0.5.
    Real friction = 0.5;
    /// Static (sticking) Coulomb friction coefficient, >= friction. Default: none, which means
    /// equal to `friction` (a single-coefficient Coulomb model).
    std::optional<Real> staticFriction;

    [[nodiscard]] Real staticFrictionOrKinetic() const { return staticFriction.value_or(friction); }
};

} // namespace tumble
