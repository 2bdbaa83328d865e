// The soft step's warm start (docs/physics/12-soft-step.md, (12.5)): each contact's last
// impulses, kept by its owner from one step to the next.
#pragma once

#include "body_slot.hpp"
#include "dynamics/soft_contact_solver.hpp"
#include "step/coupled_step.hpp"
#include "step/island_contacts.hpp"

#include <array>
#include <cstdint>
#include <span>

namespace tumble {

/// What a contact's owner kept of it last step, matched to the contact's points now.
struct KeptImpulses {
    /// Whether the owner kept the contact at all.
    bool found = false;
    std::array<Real, 4> normalImpulses{};
    Vec3 frictionImpulse{0.0};
    Real twistImpulse = 0.0;
};

/// The impulses a contact's owner kept for the same other side: each point's normal impulse
/// where a point of the same feature key was kept (else one within ten contact tolerances of
/// where it is, else none), the friction impulse as a world vector, and the twist impulse.
/// Read in the narrow phase's order, owner after owner, so each owner's cache is read at once.
KeptImpulses keptImpulsesOf(const CoupledIsland& island, std::span<const BodySlot> slots,
                            const IslandContact& contact, Real tolerance);

/// Asks the memory for what contacts[k]'s owner kept, where k is the first contact of its
/// owner (a later one finds the owner's cache read already); nothing past the contacts' end.
void prefetchKeptImpulses(const CoupledIsland& island, std::span<const BodySlot> slots,
                          std::span<const IslandContact> contacts, std::size_t k);

/// Starts a manifold from its contact's kept impulses, the friction projected on its tangents.
/// A contact new to its owner starts from none.
void startFromKept(const KeptImpulses& kept, SoftManifold& manifold);

/// Keeps the contacts' impulses in their owners' caches, replacing the island's old ones:
/// `contacts` in the narrow phase's order, contact i's result at results[resultOf[i]]. Each
/// owner's contacts go to one of `threads`: with 0 < split < the island's bodies, the owners
/// before `split` to the first thread and the rest to the second (a split island's halves,
/// (12.9)). The points are kept in the frame of the pose each owner had when they were found:
/// `centres` and `orientations` by the island's index, or with none, its pose now.
void storeSoftWarmStart(const CoupledIsland& island, std::span<BodySlot> slots,
                        std::span<const IslandContact> contacts,
                        std::span<const SoftContactResult> results,
                        std::span<const std::uint32_t> resultOf, int threads,
                        std::size_t split = 0, std::span<const Vec3> centres = {},
                        std::span<const Quat> orientations = {});

} // namespace tumble
