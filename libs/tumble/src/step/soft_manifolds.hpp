// The soft step's bodies and manifolds as they stand at the step's start
// (docs/physics/12-soft-step.md, (12.3)).
#pragma once

#include "dynamics/soft_contact_solver.hpp"
#include "step/island_contacts.hpp"
#include "tumble/body.hpp"

#include <cstddef>
#include <span>

namespace tumble {

/// A body's velocities, orientation and inverse mass properties at the step's start.
SoftBody softBodyOf(const Body& body);

/// (12.3): the manifold of a contact at the bodies' poses now: anchors from each dynamic centre of
/// mass (a static side never moves, so its anchors are zero), the gaps, the normal rows and
/// the friction at the centre; impulses zero. `staticIndex` is the static solver body's index.
/// Without `rows` the rows are left for SoftLanes to build as it packs the manifold (only the
/// centre is found).
SoftManifold softManifoldOf(const IslandContact& contact, std::span<const SoftBody> bodies,
                            std::span<const Vec3> centres, std::size_t staticIndex, bool rows);

} // namespace tumble
