// Constraints kept from step to step while their inputs stay put (11.6a).
#include "step/kept_constraints.hpp"

#include "body_slot.hpp"
#include "parallel_for.hpp"
#include "step/island_contacts.hpp"

#include <algorithm>

namespace tumble {

namespace {

KeptBodyInput inputOf(const Body& body)
{
    return {{body.position, body.orientation}, body.invMass, body.shape.size};
}

bool bodyHolds(const KeptBodyInput& kept, const Body& body)
{
    return body.invMass == kept.invMass && body.shape.size == kept.size &&
           withinPairCacheReach({body.position, body.orientation}, kept.pose);
}

/// The index of the point of `manifold` with feature id `id`, or pointCount.
int pointWithId(const PairManifold& manifold, std::uint32_t id)
{
    int k = 0;
    while (k < manifold.pointCount && manifold.points[k].id != id) {
        ++k;
    }
    return k;
}

bool contactHolds(const KeptContactInput& kept, const IslandContact& contact)
{
    const PairManifold& now = contact.manifold;
    if (contact.sideA != kept.sideA || contact.sideB != kept.sideB ||
        now.pointCount != kept.manifold.pointCount ||
        lengthSquared(now.normal - kept.manifold.normal) > kKeptNormalAngle * kKeptNormalAngle) {
        return false;
    }
    // the same features, in any order: the narrow phase may list points of equal depth either way
    for (int k = 0; k < now.pointCount; ++k) {
        const PairContactPoint& point = now.points[k];
        const int then = pointWithId(kept.manifold, point.id);
        if (then == kept.manifold.pointCount ||
            lengthSquared(point.position - kept.manifold.points[then].position) >
                kKeptPointDistance * kKeptPointDistance) {
            return false;
        }
    }
    return true;
}

/// Puts a kept contact's constraints, and its recorded points, in the order of the points found
/// now (the ids are those of `input`, checked by contactHolds).
void followPointOrder(KeptContactInput& input, const PairManifold& now,
                      std::span<ContactConstraint> constraints)
{
    std::array<ContactConstraint, 4> reordered{};
    std::array<PairContactPoint, 4> points{};
    for (int k = 0; k < now.pointCount; ++k) {
        const int then = pointWithId(input.manifold, now.points[k].id);
        reordered[k] = constraints[then];
        reordered[k].point = static_cast<std::uint32_t>(k);
        points[k] = input.manifold.points[then];
    }
    std::copy_n(reordered.begin(), now.pointCount, constraints.begin());
    input.manifold.points = points;
}

} // namespace

bool keptConstraintsHold(const KeptConstraints& kept, const CoupledIsland& island,
                         std::span<const BodySlot> slots, std::span<const IslandContact> contacts,
                         int threads)
{
    if (!kept.valid || kept.bodies != island.bodies ||
        kept.contactInputs.size() != contacts.size()) {
        return false;
    }
    const bool bodyMoved = parallelAnyOf(island.bodies.size(), threads, [&](std::size_t i) {
        return !bodyHolds(kept.bodyInputs[i], slots[island.bodies[i]].body);
    });
    return !bodyMoved && !parallelAnyOf(contacts.size(), threads, [&](std::size_t k) {
        return !contactHolds(kept.contactInputs[k], contacts[k]);
    });
}

void recordKeptInputs(KeptConstraints& kept, const CoupledIsland& island,
                      std::span<const BodySlot> slots, std::span<const IslandContact> contacts,
                      int threads)
{
    kept.valid = false;
    kept.bodies = island.bodies;
    kept.bodyInputs.resize(island.bodies.size());
    parallelFor(island.bodies.size(), threads, [&](std::size_t i) {
        kept.bodyInputs[i] = inputOf(slots[island.bodies[i]].body);
    });
    kept.contactInputs.resize(contacts.size());
    parallelFor(contacts.size(), threads, [&](std::size_t k) {
        kept.contactInputs[k] = {contacts[k].sideA, contacts[k].sideB, contacts[k].manifold};
    });
}

void refreshKeptConstraints(KeptConstraints& kept, std::span<IslandContact> contacts, int threads)
{
    std::span<ContactConstraint> constraints = kept.constraints;
    std::uint32_t points = 0;
    for (IslandContact& contact : contacts) {
        contact.firstConstraint = points;
        points += static_cast<std::uint32_t>(contact.manifold.pointCount);
    }
    // each contact writes only its own constraints and its own recorded points
    parallelFor(contacts.size(), threads, [&](std::size_t index) {
        const IslandContact& contact = contacts[index];
        const std::uint32_t first = contact.firstConstraint;
        KeptContactInput& input = kept.contactInputs[index];
        const auto count = static_cast<std::size_t>(contact.manifold.pointCount);
        bool sameOrder = true;
        for (std::size_t k = 0; k < count; ++k) {
            sameOrder = sameOrder && input.manifold.points[k].id == contact.manifold.points[k].id;
        }
        if (!sameOrder) {
            followPointOrder(input, contact.manifold, constraints.subspan(first, count));
        }
        for (int k = 0; k < contact.manifold.pointCount; ++k) {
            ContactConstraint& c = constraints[first + static_cast<std::uint32_t>(k)];
            c.separation = contact.manifold.points[k].separation;
            c.kineticFriction = contact.friction;
            c.staticFriction = contact.staticFriction;
            c.restitution = contact.restitution;
        }
    });
}

} // namespace tumble
