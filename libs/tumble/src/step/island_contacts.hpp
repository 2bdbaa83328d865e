// The narrow phase of an island: the contacts of its bodies with each other, with static bodies
// and with the half-spaces, as manifolds and as solver constraints (docs/physics/11-island-solver.md).
#pragma once

#include "body_slot.hpp"
#include "collision/pair_manifold.hpp"
#include "dynamics/contact_constraint.hpp"
#include "step/coupled_step.hpp"
#include "step/owner_groups.hpp"
#include "step/step_context.hpp"

#include <span>
#include <vector>

namespace tumble {

/// One contact of the island: two sides, their manifold and the material of the pair.
struct IslandContact {
    /// Solver-body indices; the static side is the island's last solver body.
    std::uint32_t solverA = 0;
    std::uint32_t solverB = 0;
    /// The sides as the world names them: a slot index, kPlaneSide + plane index, or kGroundSide.
    std::uint32_t sideA = 0;
    std::uint32_t sideB = 0;
    /// Solver index of the body that keeps the contact's warm start, and the key it keeps it
    /// under (the other side).
    std::uint32_t owner = 0;
    std::uint32_t ownerKey = 0;
    PairManifold manifold{};
    Real restitution = 0.0;
    Real friction = 0.0;
    Real staticFriction = 0.0;
    /// Index of the contact's first constraint; its points follow in order.
    std::uint32_t firstConstraint = 0;
};

/// A dynamic body of an island as the solver sees it: its velocities and inverse mass
/// properties (11.1).
inline SolverBody solverBodyOf(const Body& body)
{
    return {body.linearVelocity, body.angularVelocity, body.invMass, body.invInertiaWorld};
}

/// (11.7): the material of a pair: the dynamic body's alone when the other side gives none,
/// else the larger restitution and the geometric means of the friction coefficients.
Material mixMaterials(const Material& dynamic, const std::optional<Material>& other);

/// How far any point of the body can move over `horizon` seconds: the centre's speed, the
/// rotation's reach at the half diagonal and gravity's drift (a bound, as in (4.7)); 0 for a
/// static body.
Real reachOver(const Body& body, const Vec3& gravity, Real horizon);

/// Whether two bodies can come within the contact tolerance of each other over a horizon:
/// no separating axis (9.2) parts them by more than the tolerance plus how far each can move
/// (`reachA`, `reachB`: reachOver over the horizon; the speculative margin of
/// findIslandContacts). A pair whose swept boxes overlap but that
/// fails this has no contact point in the step, and joins no island (10.4). `slotA < slotB`; the
/// geometry found is kept for the narrow phase (9.11); with `carry` (the soft step) it is carried
/// within (9.12). Given `manifold`, a pair that may touch gets there its points within the same
/// margin: what findIslandContacts finds for it over the same horizon, found while the pair's
/// geometry is at hand.
bool mayTouch(std::span<BodySlot> slots, std::uint32_t slotA, std::uint32_t slotB,
              Real tolerance, Real reachA, Real reachB, bool carry,
              PairManifold* manifold = nullptr);

/// mayTouch for a pair of bodies that both rest (asleep or static) (10.4b): the answer the
/// pair's owner remembers from the last test at the same poses, sizes and margin, else mayTouch's
/// (remembered). No points are found: an island woken in the step finds its resting pairs'
/// points itself.
bool restingMayTouch(std::span<BodySlot> slots, std::uint32_t slotA, std::uint32_t slotB,
                     Real tolerance, Real reachA, Real reachB, bool carry);

/// The slot whose kept pair geometry (9.11) holds the pair (slotA < slotB): the dynamic body of
/// the two, the lower if both are. Work on pairs goes to threads grouped by it (11.5c).
inline std::uint32_t pairGeometryOwner(std::span<const BodySlot> slots, std::uint32_t slotA,
                                       std::uint32_t slotB)
{
    return slots[slotA].body.isStatic() ? slotB : slotA;
}

/// The box-box geometry of the pair (slotA < slotB) deciding `margin`, kept by its owner
/// (pairGeometryOwner) under the other side's slot; with `carry`, carried within (9.12), and then
/// valid until this thread's next call.
const CuboidPairGeometry& pairGeometry(std::span<BodySlot> slots, std::uint32_t slotA,
                                       std::uint32_t slotB, Real margin, bool carry = false);

/// Contacts of the island's bodies at their current poses, every point within a speculative
/// margin that covers how far the two sides can approach each other over `horizon` seconds.
/// Writes the pair geometry of the island's bodies only. With `context.threads` > 1 each body's
/// pairs go to one thread, and the contacts are the same as from one. With `carryGeometry` (the
/// soft step) a pair's geometry is carried with its bodies while they move within (9.12).
void findIslandContacts(const CoupledIsland& island, std::span<BodySlot> slots,
                        const StepContext& context, Real horizon, bool carryGeometry,
                        std::vector<IslandContact>& contacts);

} // namespace tumble
