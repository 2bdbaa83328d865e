// Warm starting, positions and push-out of an island's bodies.
#include "step/island_motion.hpp"

#include "body_state.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/island_solver.hpp"
#include "dynamics/point_impulses.hpp"
#include "parallel_for.hpp"
#include "step/island_constraints.hpp"
#include "step/owner_groups.hpp"
#include "step/resting_load_guess.hpp"

#include <algorithm>
#include <cmath>

namespace tumble {

namespace {

/// (11.10): the share of a penetration beyond the tolerance taken out per sub-step, and the
/// sweeps of the push-out solve.
constexpr Real kPushOutFraction = 0.2;
constexpr int kPushOutSweeps = 32;
constexpr Real kPushOutConvergence = 1e-6;
/// (11.6): how far, in contact tolerances, a point may be from a cached point of its pair whose
/// features had another name and still take its impulses.
constexpr Real kWarmStartReach = 10.0;
} // namespace

namespace {

/// The point of `point`'s position in the frame of the body `owner`.
Vec3 inBodyFrame(const Body& owner, const Vec3& point)
{
    return glm::conjugate(owner.orientation) * (point - owner.position);
}

/// The entries of the owner's cache for the pair keyed `other`, [first, last): storeWarmStart
/// writes a contact's points one after another, and each pair is one contact.
std::pair<std::size_t, std::size_t> pairEntries(const std::vector<CachedContactPoint>& cache,
                                                std::uint32_t other)
{
    std::size_t first = 0;
    while (first < cache.size() && cache[first].other != other) {
        ++first;
    }
    std::size_t last = first;
    while (last < cache.size() && cache[last].other == other) {
        ++last;
    }
    return {first, last};
}

/// The unused entry in [first, last) with feature id `id`, or `last`; `used` has bit e - first
/// set for entry e taken.
std::size_t matchById(const std::vector<CachedContactPoint>& cache, std::size_t first,
                      std::size_t last, std::uint32_t& used, std::uint32_t id)
{
    for (std::size_t e = first; e < last; ++e) {
        const std::uint32_t bit = 1u << (e - first);
        if ((used & bit) == 0 && cache[e].id == id) {
            used |= bit;
            return e;
        }
    }
    return last;
}

/// The nearest unused entry in [first, last) within `reach` of `local`, or `last`: the point
/// whose features changed name without moving (a tie in the clipping) (11.6).
std::size_t matchByPosition(const std::vector<CachedContactPoint>& cache, std::size_t first,
                            std::size_t last, std::uint32_t& used, const Vec3& local, Real reach)
{
    std::size_t best = last;
    Real bestDistance = reach * reach;
    for (std::size_t e = first; e < last; ++e) {
        const Real distance = lengthSquared(cache[e].localPosition - local);
        if ((used & (1u << (e - first))) == 0 && distance <= bestDistance) {
            best = e;
            bestDistance = distance;
        }
    }
    if (best < last) {
        used |= 1u << (best - first);
    }
    return best;
}

/// Sets a constraint's impulses from a cached point's, scaled down to a shorter sub-step and
/// clamped to the cone.
void startFrom(ContactConstraint& c, const CachedContactPoint& cached, Real tau)
{
    // scaled down to a shorter sub-step, never up: a short sub-step's impulse is mostly the
    // stopping of an approach, not a force that lasts (11.6)
    const Real shorter = std::min(1.0, tau / cached.tau);
    const Vec3 friction = shorter * cached.frictionImpulse;
    startInCone(c, shorter * cached.normalImpulse, glm::dot(c.tangent1, friction),
                glm::dot(c.tangent2, friction));
}

} // namespace

void loadWarmStart(const CoupledIsland& island, std::span<const BodySlot> slots,
                   std::span<const IslandContact> contacts,
                   std::span<ContactConstraint> constraints, Real tau,
                   const WorldSettings& settings, int threads)
{
    // the points in contact of a contact new to the island get the carried weight (11.13); a
    // point new to a contact that goes on starts from nothing, as its neighbours carry the load
    // one vector per calling thread, kept from step to step (named by reference in the lambda,
    // where a thread_local would be each worker's own)
    thread_local std::vector<std::uint8_t> keptGuess;
    std::vector<std::uint8_t>& guess = keptGuess;
    guess.assign(constraints.size(), 0);
    const Real reach = kWarmStartReach * settings.contactTolerance;
    // each contact reads its owner's cache and writes only its own constraints
    parallelFor(contacts.size(), threads, [&](std::size_t index) {
        const IslandContact& contact = contacts[index];
        const BodySlot& owner = slots[island.bodies[contact.owner]];
        const std::vector<CachedContactPoint>& cache = owner.contactCache;
        // a pair keeps at most 4 points (storeWarmStart), so a bit each marks those taken
        const auto [first, last] = pairEntries(cache, contact.ownerKey);
        std::uint32_t used = 0;
        // the same features first, so a point found by position never takes another's entry
        std::array<std::size_t, 4> match{};
        for (int k = 0; k < contact.manifold.pointCount; ++k) {
            match[k] = matchById(cache, first, last, used, contact.manifold.points[k].id);
        }
        bool goesOn = false;
        for (int k = 0; k < contact.manifold.pointCount; ++k) {
            if (match[k] == last && first < last) {
                match[k] = matchByPosition(
                    cache, first, last, used,
                    inBodyFrame(owner.body, contact.manifold.points[k].position), reach);
            }
            goesOn = goesOn || match[k] < last;
        }
        for (int k = 0; k < contact.manifold.pointCount; ++k) {
            ContactConstraint& c = constraints[contact.firstConstraint + k];
            c.normalImpulse = 0.0;
            c.tangentImpulse1 = 0.0;
            c.tangentImpulse2 = 0.0;
            if (match[k] < last) {
                startFrom(c, cache[match[k]], tau);
            } else if (!goesOn && c.separation <= settings.contactTolerance) {
                guess[contact.firstConstraint + static_cast<std::uint32_t>(k)] = 1;
            }
        }
    });
    if (std::find(guess.begin(), guess.end(), std::uint8_t{1}) != guess.end()) {
        guessRestingImpulses(island, slots, contacts, constraints, guess, settings.gravity, tau);
    }
}

void storeWarmStart(const CoupledIsland& island, std::span<BodySlot> slots,
                    std::span<const IslandContact> contacts,
                    std::span<const ContactConstraint> constraints, Real tau, int threads)
{
    // each body's cache is written by its own contacts only, in their order (as from one pass)
    const OwnerGroups& groups = contactsByOwner(contacts, island.bodies.size());
    for (const std::uint32_t slot : island.bodies) {
        slots[slot].contactCache.clear();
    }
    parallelFor(groups.count(), threads, [&](std::size_t g) {
        for (const std::uint32_t index : groups.group(g)) {
            const IslandContact& contact = contacts[index];
            BodySlot& owner = slots[island.bodies[contact.owner]];
            for (int k = 0; k < contact.manifold.pointCount; ++k) {
                const ContactConstraint& c = constraints[contact.firstConstraint + k];
                if (c.normalImpulse <= 0.0) {
                    continue;
                }
                const PairContactPoint& point = contact.manifold.points[k];
                owner.contactCache.push_back(
                    {contact.ownerKey, point.id, inBodyFrame(owner.body, point.position),
                     c.normalImpulse,
                     c.tangentImpulse1 * c.tangent1 + c.tangentImpulse2 * c.tangent2, tau});
            }
        }
    });
}

void BodyConstraintLists::build(std::span<const ContactConstraint> constraints,
                                std::size_t bodyCount, int threads)
{
    ends.resize(constraints.size());
    parallelFor(constraints.size(), threads, [&](std::size_t k) {
        ends[k] = {constraints[k].bodyA, constraints[k].bodyB};
    });
    // counting sort by body: each constraint is listed under each dynamic body it touches
    starts.assign(bodyCount + 2, 0);
    for (const auto& bodies : ends) {
        for (const std::uint32_t body : bodies) {
            if (body < bodyCount) {
                ++starts[body + 2];
            }
        }
    }
    for (std::size_t i = 2; i < starts.size(); ++i) {
        starts[i] += starts[i - 1];
    }
    indices.resize(starts.back());
    for (std::uint32_t index = 0; index < ends.size(); ++index) {
        for (const std::uint32_t body : ends[index]) {
            if (body < bodyCount) {
                indices[starts[body + 1]++] = index;
            }
        }
    }
    starts.pop_back();
}

void integrateIslandBody(Body& body, const Vec3& velocityStart,
                         std::span<const ContactConstraint> constraints,
                         std::span<const std::uint32_t> bodyConstraints, Real tau,
                         Integrator integrator)
{
    // an orthonormal basis of the normals that pushed on the body (Gram-Schmidt, at most 3)
    std::array<Vec3, 3> basis{};
    int dimension = 0;
    for (const std::uint32_t index : bodyConstraints) {
        const ContactConstraint& c = constraints[index];
        if (dimension == 3 || c.normalImpulse <= 0.0) {
            continue;
        }
        Vec3 direction = c.normal;
        for (int k = 0; k < dimension; ++k) {
            direction -= glm::dot(basis[k], direction) * basis[k];
        }
        const Real length = glm::length(direction);
        if (length > 1e-6) {
            basis[dimension++] = direction / length;
        }
    }
    Vec3 velocity = integrator == Integrator::Exact ? 0.5 * (velocityStart + body.linearVelocity)
                                                    : body.linearVelocity;
    for (int k = 0; k < dimension; ++k) {
        velocity += glm::dot(basis[k], body.linearVelocity - velocity) * basis[k];
    }
    body.position += tau * velocity;
    integrateRotation(body, tau, integrator);
}

void pushOutOfPenetration(const CoupledIsland& island, std::span<BodySlot> slots,
                          std::span<const ContactConstraint> constraints, Real tau,
                          const WorldSettings& settings, int threads)
{
    const std::size_t count = island.bodies.size();
    // the points that will be deeper than the tolerance at the end of the sub-step (none in a
    // settled pile, which then costs one pass over its constraints), by how much
    thread_local std::vector<Real> keptExcess;
    std::vector<Real>& excess = keptExcess;
    excess.resize(constraints.size());
    parallelFor(constraints.size(), threads, [&](std::size_t k) {
        const ContactConstraint& c = constraints[k];
        const Body* bodyA = c.bodyA < count ? &slots[island.bodies[c.bodyA]].body : nullptr;
        const Body* bodyB = c.bodyB < count ? &slots[island.bodies[c.bodyB]].body : nullptr;
        const Vec3 velocityA = bodyA ? bodyA->velocityAt(bodyA->position + c.offsetA) : Vec3(0.0);
        const Vec3 velocityB = bodyB ? bodyB->velocityAt(bodyB->position + c.offsetB) : Vec3(0.0);
        const Real predicted = c.separation + tau * glm::dot(c.normal, velocityB - velocityA);
        excess[k] = -predicted - settings.contactTolerance;
    });
    std::vector<ContactConstraint> deep;
    for (std::size_t k = 0; k < constraints.size(); ++k) {
        if (excess[k] <= 0.0) {
            continue;
        }
        ContactConstraint& push = deep.emplace_back(constraints[k]);
        push.normalImpulse = 0.0;
        push.tangentImpulse1 = 0.0;
        push.tangentImpulse2 = 0.0;
        push.kineticFriction = 0.0;
        push.staticFriction = 0.0;
        push.targetNormalVelocity = kPushOutFraction * excess[k] / tau;
    }
    if (deep.empty()) {
        return;
    }
    std::vector<SolverBody> pseudo(count + 1);
    for (std::size_t i = 0; i < count; ++i) {
        const Body& body = slots[island.bodies[i]].body;
        pseudo[i].invMass = body.invMass;
        pseudo[i].invInertiaWorld = body.invInertiaWorld;
    }
    for (ContactConstraint& push : deep) {
        // the push-out's target (11.10) replaces the one prepareConstraint sets
        const Real target = push.targetNormalVelocity;
        prepareConstraint(push, pseudo, {ConstraintTarget::Substep, tau, 0.0, 0.0});
        push.targetNormalVelocity = target;
    }
    solveConstraints(deep, pseudo, kPushOutSweeps, kPushOutConvergence, 0.0, threads);
    for (std::size_t i = 0; i < count; ++i) {
        Body& body = slots[island.bodies[i]].body;
        if (lengthSquared(pseudo[i].linearVelocity) + lengthSquared(pseudo[i].angularVelocity) ==
            0.0) {
            continue;
        }
        body.position += tau * pseudo[i].linearVelocity;
        const Vec3 turn = tau * pseudo[i].angularVelocity;
        const Real angle = glm::length(turn);
        if (angle > 0.0) {
            body.orientation = glm::normalize(axisAngle(turn / angle, angle) * body.orientation);
            refreshWorldInertia(body);
        }
    }
}

void markTouching(const CoupledIsland& island, std::span<BodySlot> slots,
                  std::span<const ContactConstraint> constraints,
                  const BodyConstraintLists& constraintsOf, Real tolerance, int threads)
{
    parallelFor(island.bodies.size(), threads, [&](std::size_t i) {
        const std::span<const std::uint32_t> own = constraintsOf.of(i);
        slots[island.bodies[i]].touchingGround =
            std::any_of(own.begin(), own.end(), [&](const std::uint32_t k) {
                return constraints[k].separation <= tolerance ||
                       constraints[k].normalImpulse > 0.0;
            });
    });
}

} // namespace tumble
