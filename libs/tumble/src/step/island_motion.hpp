// What the island step does around its solves: warm starting from last step's impulses,
// positions, the push-out and the touching flags (docs/physics/11-island-solver.md).
#pragma once

#include "body_slot.hpp"
#include "dynamics/contact_constraint.hpp"
#include "step/coupled_step.hpp"
#include "step/island_contacts.hpp"

#include <array>
#include <span>
#include <vector>

namespace tumble {

/// (11.6): each constraint starts from its point's impulses of the last sub-step, scaled down to
/// a shorter tau (never up) and clamped to its cone; a point in contact with none starts from the
/// weight it carries (11.13). The contacts spread over `threads`.
void loadWarmStart(const CoupledIsland& island, std::span<const BodySlot> slots,
                   std::span<const IslandContact> contacts,
                   std::span<ContactConstraint> constraints, Real tau,
                   const WorldSettings& settings, int threads = 1);

/// Keeps the impulses of a solve of length tau, and tau, in the owners' caches; each owner's
/// contacts go to one of `threads`.
void storeWarmStart(const CoupledIsland& island, std::span<BodySlot> slots,
                    std::span<const IslandContact> contacts,
                    std::span<const ContactConstraint> constraints, Real tau, int threads = 1);

/// The constraints of each body of an island, in order: body i's are
/// indices[starts[i]] .. indices[starts[i + 1]] (the static solver body has none).
struct BodyConstraintLists {
    std::vector<std::uint32_t> starts;
    std::vector<std::uint32_t> indices;
    /// The bodies of each constraint, gathered over the threads so the sort reads them packed.
    std::vector<std::array<std::uint32_t, 2>> ends;

    void build(std::span<const ContactConstraint> constraints, std::size_t bodyCount,
               int threads = 1);
    [[nodiscard]] std::span<const std::uint32_t> of(std::size_t body) const
    {
        return {indices.data() + starts[body], indices.data() + starts[body + 1]};
    }
};

/// (11.9): the body's translation and rotation over tau. The centre moves with the mean of the
/// start and end velocities (2.2), except along the normals of the points that pushed on it,
/// where it moves with the end velocity they allowed (the rule (2.2a) of a body alone).
/// `bodyConstraints` are the indices of the body's constraints, in order.
void integrateIslandBody(Body& body, const Vec3& velocityStart,
                         std::span<const ContactConstraint> constraints,
                         std::span<const std::uint32_t> bodyConstraints, Real tau,
                         Integrator integrator);

/// (11.10): points predicted to end the sub-step deeper than the contact tolerance are pushed
/// apart by a fraction of the excess with pseudo-velocities that move the poses only, so the
/// push-out adds no kinetic energy. The points spread over `threads`, as in solveConstraints.
void pushOutOfPenetration(const CoupledIsland& island, std::span<BodySlot> slots,
                          std::span<const ContactConstraint> constraints, Real tau,
                          const WorldSettings& settings, int threads = 1);

/// Marks the island's bodies that end the sub-step in contact with anything: those with a
/// point in contact or one that pushed. Each body reads its own constraints, spread over
/// `threads`.
void markTouching(const CoupledIsland& island, std::span<BodySlot> slots,
                  std::span<const ContactConstraint> constraints,
                  const BodyConstraintLists& constraintsOf, Real tolerance, int threads = 1);

} // namespace tumble
