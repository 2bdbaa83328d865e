// What the exact step builds from an island's contacts (docs/physics/11-island-solver.md).
#include "step/island_constraints.hpp"

#include "dynamics/island_solver.hpp"
#include "parallel_for.hpp"

namespace tumble {

void buildConstraints(std::span<IslandContact> contacts, std::span<const BodySlot> slots,
                      const CoupledIsland& island, std::vector<ContactConstraint>& constraints,
                      int threads)
{
    const auto staticIndex = static_cast<std::uint32_t>(island.bodies.size());
    const auto centreOf = [&](std::uint32_t solver, std::uint32_t side, const Vec3& point) {
        if (solver != staticIndex) {
            return slots[island.bodies[solver]].body.position;
        }
        // a static body turns about its centre; a half-space has no centre (nothing turns it)
        return side < kPlaneSide ? slots[side].body.position : point;
    };
    std::uint32_t points = 0;
    for (IslandContact& contact : contacts) {
        contact.firstConstraint = points;
        points += static_cast<std::uint32_t>(contact.manifold.pointCount);
    }
    constraints.resize(points);
    // the static side is the solver body of zero inverses, as in the step's solver bodies
    const auto sideOf = [&](std::uint32_t solver) {
        return solver != staticIndex ? solverBodyOf(slots[island.bodies[solver]].body)
                                     : SolverBody{};
    };
    // each contact writes only its own constraints, geometry prepared while they are at hand
    parallelFor(contacts.size(), threads, [&](std::size_t index) {
        const IslandContact& contact = contacts[index];
        const SolverBody a = sideOf(contact.solverA);
        const SolverBody b = sideOf(contact.solverB);
        for (int k = 0; k < contact.manifold.pointCount; ++k) {
            const PairContactPoint& point = contact.manifold.points[k];
            ContactConstraint& c = constraints[contact.firstConstraint + k];
            c = ContactConstraint{};
            c.bodyA = contact.solverA;
            c.bodyB = contact.solverB;
            c.contact = static_cast<std::uint32_t>(index);
            c.point = static_cast<std::uint32_t>(k);
            c.normal = contact.manifold.normal;
            c.offsetA = point.position - centreOf(contact.solverA, contact.sideA, point.position);
            c.offsetB = point.position - centreOf(contact.solverB, contact.sideB, point.position);
            c.separation = point.separation;
            c.kineticFriction = contact.friction;
            c.staticFriction = contact.staticFriction;
            c.restitution = contact.restitution;
            prepareConstraintGeometry(c, a, b);
        }
    });
}

const OwnerGroups& contactsByOwner(std::span<const IslandContact> contacts, std::size_t bodies)
{
    thread_local std::vector<std::uint32_t> ownerOf;
    thread_local OwnerGroups groups;
    ownerOf.resize(contacts.size());
    for (std::size_t index = 0; index < contacts.size(); ++index) {
        ownerOf[index] = contacts[index].owner;
    }
    groups.build(ownerOf, bodies);
    return groups;
}

} // namespace tumble
