// Impact events and contact records of an island.
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

/// Calls visit(contact, points) for each contact with the span of its constraints, which follow
/// one another in the solver's order.
template <typename Visit>
void forEachContact(std::span<const IslandContact> contacts,
                    std::span<const ContactConstraint> constraints, Visit visit)
{
    for (std::size_t first = 0; first < constraints.size();) {
        std::size_t last = first;
        while (last < constraints.size() &&
               constraints[last].contact == constraints[first].contact) {
            ++last;
        }
        visit(contacts[constraints[first].contact], constraints.subspan(first, last - first));
        first = last;
    }
}

/// A contact as its reporting side sees it: the moving side that brought more kinetic energy,
/// its normal into that side, impulses and relative velocities acting on it.
ContactManifold reportedManifold(const IslandContact& contact,
                                 std::span<const ContactConstraint> points,
                                 std::span<const BodySlot> slots,
                                 std::span<const SolverBody> bodies, std::size_t count,
                                 std::span<const Real> kinetic)
{
    const bool ofA = contact.solverA < count &&
                     (contact.solverB >= count ||
                      kinetic[contact.solverA] > kinetic[contact.solverB]);
    const Real sign = ofA ? -1.0 : 1.0;
    const std::uint32_t otherSide = ofA ? contact.sideB : contact.sideA;
    ContactManifold manifold;
    manifold.body = idOf(slots, ofA ? contact.sideA : contact.sideB);
    manifold.other = idOf(slots, otherSide);
    manifold.plane = otherSide >= kPlaneSide && otherSide != kGroundSide
                         ? static_cast<int>(otherSide - kPlaneSide)
                         : -1;
    manifold.normal = sign * contact.manifold.normal;
    for (const ContactConstraint& c : points) {
        ContactPoint& point = manifold.points[manifold.pointCount++];
        const PairContactPoint& source = contact.manifold.points[c.point];
        const Vec3 after = bodies[c.bodyB].velocityAt(c.offsetB) - bodies[c.bodyA].velocityAt(c.offsetA);
        point.vertex = otherSide >= kPlaneSide ? static_cast<int>(source.id) : -1;
        point.position = source.position;
        point.penetration = -source.separation;
        point.normalImpulse = c.normalImpulse;
        point.frictionImpulse =
            sign * (c.tangentImpulse1 * c.tangent1 + c.tangentImpulse2 * c.tangent2);
        point.velocityBefore = sign * c.velocityBefore;
        point.velocityAfter = sign * after;
        const Real bound = c.friction * c.normalImpulse;
        point.sliding = bound > 0.0 && glm::length(point.frictionImpulse) >= (1.0 - 1e-9) * bound;
        point.restitution = c.restitutionState;
    }
    return manifold;
}

} // namespace

void recordIslandImpacts(const CoupledIsland& island, std::span<const BodySlot> slots,
                         std::span<const IslandContact> contacts,
                         std::span<const ContactConstraint> impact,
                         std::span<const SolverBody> bodies, std::span<const Real> kineticBefore,
                         Real impactSpeed, Real time, StepEvents& events)
{
    const std::size_t count = island.bodies.size();
    forEachContact(contacts, impact, [&](const IslandContact& contact, auto points) {
        const bool hit = std::any_of(points.begin(), points.end(), [&](const auto& c) {
            return c.normalImpulse > 0.0 && c.normalVelocityBefore < -impactSpeed;
        });
        if (!hit) {
            return;
        }
        CollisionEvent event;
        event.time = time;
        event.manifold = reportedManifold(contact, points, slots, bodies, count, kineticBefore);
        for (int k = 0; k < event.manifold.pointCount; ++k) {
            const ContactPoint& point = event.manifold.points[k];
            event.approachSpeed = std::max(event.approachSpeed, -points[k].normalVelocityBefore);
            event.normalImpulse += point.normalImpulse * event.manifold.normal;
            event.frictionImpulse += point.frictionImpulse;
            event.restitutionApplied |= point.restitution == RestitutionState::Applied;
            event.restitution = std::max(event.restitution, points[k].restitution);
        }
        for (const std::uint32_t solver : {contact.solverA, contact.solverB}) {
            if (solver < count) {
                event.kineticEnergyBefore += kineticBefore[solver];
                event.kineticEnergyAfter += slots[island.bodies[solver]].body.kineticEnergy();
            }
        }
        events.collisions.push_back(event);
    });
}

void recordIslandContacts(ContactPhase phase, const CoupledIsland& island,
                          std::span<const BodySlot> slots, std::span<const IslandContact> contacts,
                          std::span<const ContactConstraint> constraints,
                          std::span<const SolverBody> bodies, std::span<const Real> kinetic,
                          Real tolerance, Real time, StepEvents& events)
{
    const std::size_t count = island.bodies.size();
    forEachContact(contacts, constraints, [&](const IslandContact& contact, auto points) {
        const bool touching = std::any_of(points.begin(), points.end(), [&](const auto& c) {
            return c.separation <= tolerance || c.normalImpulse > 0.0;
        });
        if (!touching) {
            return;
        }
        ContactRecord record;
        record.time = time;
        record.phase = phase;
        record.manifold = reportedManifold(contact, points, slots, bodies, count, kinetic);
        record.centreOfMass = slots[record.manifold.body.index].body.position;
        events.contactRecords.push_back(record);
    });
}

} // namespace tumble
