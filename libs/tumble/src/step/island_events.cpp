// Impact events of an island.
#include "step/island_events.hpp"

#include <algorithm>

namespace tumble {

namespace {

BodyId idOf(std::span<const BodySlot> slots, std::uint32_t side)
{
    if (side >= kPlaneSide) {
        return BodyId{};
    }
    return BodyId{side, slots[side].generation};
}

} // namespace

void recordIslandImpacts(const CoupledIsland& island, std::span<const BodySlot> slots,
                         std::span<const IslandContact> contacts,
                         std::span<const ContactConstraint> impact,
                         std::span<const Real> kineticBefore, Real impactSpeed, Real time,
                         StepEvents& events)
{
    const std::size_t count = island.bodies.size();
    for (std::size_t first = 0; first < impact.size();) {
        std::size_t last = first;
        while (last < impact.size() && impact[last].contact == impact[first].contact) {
            ++last;
        }
        const IslandContact& contact = contacts[impact[first].contact];
        const std::span<const ContactConstraint> points = impact.subspan(first, last - first);
        first = last;
        const bool hit = std::any_of(points.begin(), points.end(), [&](const auto& c) {
            return c.normalImpulse > 0.0 && c.normalVelocityBefore < -impactSpeed;
        });
        if (!hit) {
            continue;
        }
        // the event belongs to the moving side that brought more kinetic energy to the impact
        const bool ofA = contact.solverA < count &&
                         (contact.solverB >= count ||
                          kineticBefore[contact.solverA] > kineticBefore[contact.solverB]);
        const Real sign = ofA ? -1.0 : 1.0;
        CollisionEvent event;
        event.time = time;
        ContactManifold& manifold = event.manifold;
        manifold.body = idOf(slots, ofA ? contact.sideA : contact.sideB);
        const std::uint32_t otherSide = ofA ? contact.sideB : contact.sideA;
        manifold.other = idOf(slots, otherSide);
        manifold.plane = otherSide >= kPlaneSide && otherSide != kGroundSide
                             ? static_cast<int>(otherSide - kPlaneSide)
                             : -1;
        manifold.normal = sign * contact.manifold.normal;
        for (const ContactConstraint& c : points) {
            ContactPoint& point = manifold.points[manifold.pointCount++];
            const PairContactPoint& source = contact.manifold.points[c.point];
            point.vertex = otherSide >= kPlaneSide ? static_cast<int>(source.id) : -1;
            point.position = source.position;
            point.penetration = -source.separation;
            point.normalImpulse = c.normalImpulse;
            point.frictionImpulse =
                sign * (c.tangentImpulse1 * c.tangent1 + c.tangentImpulse2 * c.tangent2);
            point.restitution = c.restitutionState;
            event.approachSpeed = std::max(event.approachSpeed, -c.normalVelocityBefore);
            event.normalImpulse += sign * c.normalImpulse * c.normal;
            event.frictionImpulse += point.frictionImpulse;
            event.restitutionApplied |= c.restitutionState == RestitutionState::Applied;
        }
        for (const std::uint32_t solver : {contact.solverA, contact.solverB}) {
            if (solver < count) {
                event.kineticEnergyBefore += kineticBefore[solver];
                event.kineticEnergyAfter += slots[island.bodies[solver]].body.kineticEnergy();
            }
        }
        events.collisions.push_back(event);
    }
}

} // namespace tumble
