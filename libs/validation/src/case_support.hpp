// Helpers shared by the validation cases: worlds with the installed fault, quantities, stepping.
#pragma once

#include "tumble/validation/validation.hpp"
#include "tumble/world.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace tumble::validation {

/// Standard gravity of the cases, m/s^2.
inline constexpr Real kGravity = 9.81;

/// A world with `settings` and the fault of setFaultForTesting applied.
World makeWorld(WorldSettings settings, bool withGround);

/// A body definition with the fault applied to its restitution.
BodyDef withFault(BodyDef def);

/// The 2 x 6 x 2 handout cuboid of the given mass.
BodyDef handoutCuboid(Real mass);

/// Steps `world` by dt until `seconds` have passed (rounded to whole steps).
void simulate(World& world, Real seconds, Real dt);

Quantity quantity(std::string name, Real exact, Real value, Real tolerance, std::string unit);

/// Cases of each file, appended in document order.
void addRigidBodyCases(std::vector<Case>& cases);
void addContactCases(std::vector<Case>& cases);
void addTouchingCases(std::vector<Case>& cases);

} // namespace tumble::validation
