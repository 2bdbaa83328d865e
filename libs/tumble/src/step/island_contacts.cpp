// Narrow phase of an island: box-box, box-static box, box-half-space.
#include "step/island_contacts.hpp"

#include "collision/collide_cuboid_cuboid.hpp"
#include "collision/collide_cuboid_half_space.hpp"
#include "dynamics/island_solver.hpp"
#include "parallel_for.hpp"
#include "step/owner_groups.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace tumble {

namespace {

/// reachOver of each of the island's bodies, then 0 for the static side; one vector per thread,
/// kept from step to step.
std::span<const Real> islandReach(const CoupledIsland& island, std::span<const BodySlot> slots,
                                  const Vec3& gravity, Real horizon)
{
    thread_local std::vector<Real> reach;
    reach.resize(island.bodies.size() + 1);
    for (std::size_t local = 0; local < island.bodies.size(); ++local) {
        reach[local] = reachOver(slots[island.bodies[local]].body, gravity, horizon);
    }
    reach.back() = 0.0;
    return reach;
}

/// Bodies a thread takes at a time in the half-space tests.
constexpr std::size_t kHalfSpaceBodiesPerChunk = 64;

void setMaterial(IslandContact& contact, const Material& material)
{
    contact.restitution = material.restitution;
    contact.friction = material.friction;
    contact.staticFriction = material.staticFrictionOrKinetic();
}

/// The contacts of the island's bodies with the ground and the static planes, body by body and
/// in that order, each body's found on one of `threads` threads.
void addHalfSpaceContacts(const CoupledIsland& island, std::span<const BodySlot> slots,
                          const StepContext& context, std::span<const Real> reach, int threads,
                          std::vector<IslandContact>& contacts)
{
    const std::size_t sides = (context.ground ? 1 : 0) + context.planes.size();
    if (sides == 0) {
        return;
    }
    const auto staticIndex = static_cast<std::uint32_t>(island.bodies.size());
    const Real tolerance = context.settings.contactTolerance;
    // kept from step to step by the calling thread, named below through these references
    thread_local std::vector<IslandContact> keptFound;
    thread_local std::vector<std::uint8_t> keptTouches;
    std::vector<IslandContact>& found = keptFound;
    std::vector<std::uint8_t>& touches = keptTouches;
    found.resize(island.bodies.size() * sides);
    touches.assign(found.size(), 0);
    // the bodies near a half-space (a pile's lowest layer) lie together in the island's order
    parallelForBalanced(island.bodies.size(), threads, kHalfSpaceBodiesPerChunk,
                        [&](std::size_t index) {
        const auto local = static_cast<std::uint32_t>(index);
        const Body& body = slots[island.bodies[local]].body;
        const Transform pose{body.position, body.orientation};
        const Real margin = tolerance + reach[local];
        std::size_t slot = index * sides;
        const auto addContact = [&](const Vec3& point, const Vec3& normal, std::uint32_t side,
                                    const std::optional<Material>& material) {
            const PairManifold manifold =
                collideCuboidHalfSpace(pose, body.shape.halfExtents(), point, normal, margin);
            const std::size_t here = slot++;
            touches[here] = manifold.pointCount > 0 ? 1 : 0;
            if (manifold.pointCount == 0) {
                return;
            }
            IslandContact contact;
            contact.manifold = manifold;
            contact.solverA = staticIndex;
            contact.solverB = local;
            contact.sideA = side;
            contact.sideB = island.bodies[local];
            contact.owner = local;
            contact.ownerKey = side;
            setMaterial(contact, mixMaterials(body.material, material));
            found[here] = contact;
        };
        if (context.ground) {
            addContact(Vec3(0.0, context.ground->height, 0.0), Plane::normal(), kGroundSide,
                       context.groundMaterial);
        }
        for (std::uint32_t k = 0; k < context.planes.size(); ++k) {
            const StaticPlane& plane = context.planes[k];
            addContact(plane.point, plane.normal, kPlaneSide + k, plane.material);
        }
    });
    for (std::size_t slot = 0; slot < found.size(); ++slot) {
        if (touches[slot] != 0) {
            contacts.push_back(found[slot]);
        }
    }
}

} // namespace

Real reachOver(const Body& body, const Vec3& gravity, Real horizon)
{
    if (body.isStatic()) {
        return 0.0;
    }
    const Real drift = glm::length(gravity) * horizon;
    if (body.linearVelocity == Vec3(0.0) && body.angularVelocity == Vec3(0.0)) {
        // a body asleep: 0 + 0 r + drift is drift, bit for bit
        return horizon * drift;
    }
    const Real radius = glm::length(body.shape.halfExtents());
    return horizon *
           (glm::length(body.linearVelocity) + glm::length(body.angularVelocity) * radius + drift);
}

Material mixMaterials(const Material& dynamic, const std::optional<Material>& other)
{
    if (!other) {
        return dynamic;
    }
    Material mixed;
    mixed.restitution = std::max(dynamic.restitution, other->restitution);
    mixed.friction = std::sqrt(dynamic.friction * other->friction);
    mixed.staticFriction =
        std::sqrt(dynamic.staticFrictionOrKinetic() * other->staticFrictionOrKinetic());
    return mixed;
}

const CuboidPairGeometry& pairGeometry(std::span<BodySlot> slots, std::uint32_t slotA,
                                       std::uint32_t slotB, Real margin, bool carry)
{
    const Body& a = slots[slotA].body;
    const Body& b = slots[slotB].body;
    // kept under the other side's slot, so that a body's pairs with two static boxes are apart
    const std::uint32_t owner = pairGeometryOwner(slots, slotA, slotB);
    const std::uint32_t other = owner == slotA ? slotB : slotA;
    // a carried geometry is read at once by the caller, on this thread (9.12)
    thread_local CuboidPairGeometry carried;
    return slots[owner].pairGeometry.geometry(other, {a.position, a.orientation},
                                              a.shape.halfExtents(), {b.position, b.orientation},
                                              b.shape.halfExtents(), margin,
                                              carry ? &carried : nullptr);
}

bool mayTouch(std::span<BodySlot> slots, std::uint32_t slotA, std::uint32_t slotB,
              Real tolerance, Real reachA, Real reachB, bool carry, PairManifold* manifold)
{
    // the margin of findPairContact, summed in the same order
    const Real margin = tolerance + reachA + reachB;
    const CuboidPairGeometry& geometry = pairGeometry(slots, slotA, slotB, margin, carry);
    const bool touches = !(geometry.largestSeparation > margin);
    if (touches && manifold != nullptr) {
        writeManifoldWithin(geometry, margin, *manifold);
    }
    return touches;
}

bool restingMayTouch(std::span<BodySlot> slots, std::uint32_t slotA, std::uint32_t slotB,
                     Real tolerance, Real reachA, Real reachB, bool carry)
{
    const Real margin = tolerance + reachA + reachB;
    const Body& a = slots[slotA].body;
    const Body& b = slots[slotB].body;
    const Transform poseA{a.position, a.orientation};
    const Transform poseB{b.position, b.orientation};
    const std::uint32_t owner = pairGeometryOwner(slots, slotA, slotB);
    const std::uint32_t other = owner == slotA ? slotB : slotA;
    PairGeometryCache& kept = slots[owner].pairGeometry;
    if (const std::optional<bool> touches = kept.restingTouch(
            other, poseA, a.shape.halfExtents(), poseB, b.shape.halfExtents(), margin)) {
        return *touches;
    }
    const bool touches = mayTouch(slots, slotA, slotB, tolerance, reachA, reachB, carry);
    kept.rememberRestingTouch(other, poseA, poseB, margin, touches);
    return touches;
}

namespace {

/// Whether the narrow phase reads the pairs' manifolds found by the broad phase's test: a step
/// over the same horizon with carried geometry (the soft step) on an island that has them.
bool readsFoundManifolds(const CoupledIsland& island, bool carry)
{
    return carry && island.pairManifolds.size() == island.pairs.size() &&
           island.pairHasPoints.size() == island.pairs.size() && !island.pairs.empty();
}

/// The contact of the island's pair k, if any point is within the margin.
bool findPairContact(const CoupledIsland& island, std::span<BodySlot> slots, Real tolerance,
                     std::span<const Real> reach, bool carry, std::size_t k,
                     IslandContact& contact)
{
    const auto [slotA, slotB] = island.pairs[k];
    const Body& a = slots[slotA].body;
    const Body& b = slots[slotB].body;
    const auto [solverA, solverB] = island.pairSolvers[k];
    if (readsFoundManifolds(island, carry)) {
        contact.manifold = *island.pairManifolds[k];
    } else {
        const Real margin = tolerance + reach[solverA] + reach[solverB];
        writeManifoldWithin(pairGeometry(slots, slotA, slotB, margin, carry), margin,
                            contact.manifold);
    }
    if (contact.manifold.pointCount == 0) {
        return false;
    }
    contact.solverA = solverA;
    contact.solverB = solverB;
    contact.sideA = slotA;
    contact.sideB = slotB;
    // the lower dynamic body keeps the warm start; a static side never does
    const bool aKeeps = !a.isStatic();
    contact.owner = aKeeps ? contact.solverA : contact.solverB;
    contact.ownerKey = aKeeps ? slotB : slotA;
    const Material material =
        a.isStatic()   ? mixMaterials(b.material, a.materialGiven ? std::optional(a.material)
                                                                  : std::nullopt)
        : b.isStatic() ? mixMaterials(a.material, b.materialGiven ? std::optional(b.material)
                                                                  : std::nullopt)
                       : mixMaterials(a.material, b.material);
    setMaterial(contact, material);
    return true;
}

/// findPairContact for each pair over `threads` threads: each body's pairs go to one thread,
/// since a pair writes the geometry its dynamic body keeps (9.11), unless the manifolds were
/// found by the broad phase (then no pair writes anything shared); `contacts` then holds the
/// contacts in the order of the pairs, as from one thread (11.5c).
void findPairContactsOverThreads(const CoupledIsland& island, std::span<BodySlot> slots,
                                 Real tolerance, std::span<const Real> reach, bool carry,
                                 int threads, std::vector<IslandContact>& contacts)
{
    // kept from step to step by the calling thread; the lambdas below name them through these
    // references, since a thread_local named there would be each worker's own
    thread_local std::vector<std::uint32_t> keptPlace;
    std::vector<std::uint32_t>& place = keptPlace;
    const std::size_t pairs = island.pairs.size();
    place.resize(pairs);
    if (readsFoundManifolds(island, carry)) {
        // which pairs touch is known from their manifolds: each contact is written once, at
        // its place (a megabyte on the pyramid, copied twice otherwise)
        std::uint32_t count = 0;
        for (std::size_t k = 0; k < pairs; ++k) {
            place[k] = count;
            count += island.pairHasPoints[k];
        }
        contacts.resize(count);
        parallelFor(pairs, threads, [&](std::size_t k) {
            if (island.pairHasPoints[k] != 0) {
                findPairContact(island, slots, tolerance, reach, carry, k, contacts[place[k]]);
            }
        });
        return;
    }
    thread_local std::vector<IslandContact> keptOfPair;
    thread_local std::vector<std::uint32_t> keptOwnerOf;
    thread_local OwnerGroups keptGroups;
    thread_local std::vector<std::uint8_t> keptFound;
    std::vector<IslandContact>& ofPair = keptOfPair;
    std::vector<std::uint8_t>& found = keptFound;
    std::vector<std::uint32_t>& ownerOf = keptOwnerOf;
    OwnerGroups& groups = keptGroups;
    ofPair.resize(pairs);
    found.resize(pairs);
    ownerOf.resize(pairs);
    parallelFor(pairs, threads, [&](std::size_t k) {
        const auto [slotA, slotB] = island.pairs[k];
        const auto& [solverA, solverB] = island.pairSolvers[k];
        ownerOf[k] = pairGeometryOwner(slots, slotA, slotB) == slotA ? solverA : solverB;
    });
    groups.build(ownerOf, island.bodies.size());
    parallelFor(groups.count(), threads, [&](std::size_t g) {
        for (const std::uint32_t k : groups.group(g)) {
            found[k] =
                findPairContact(island, slots, tolerance, reach, carry, k, ofPair[k]) ? 1 : 0;
        }
    });
    // each found contact to its place in the order of the pairs
    std::uint32_t count = 0;
    for (std::size_t k = 0; k < pairs; ++k) {
        place[k] = count;
        count += found[k];
    }
    // every kept entry is overwritten below: resizing without clearing first builds none of
    // them (a serial pass over a megabyte on the pyramid)
    contacts.resize(count);
    parallelFor(pairs, threads, [&](std::size_t k) {
        if (found[k] != 0) {
            contacts[place[k]] = ofPair[k];
        }
    });
}

} // namespace

void findIslandContacts(const CoupledIsland& island, std::span<BodySlot> slots,
                        const StepContext& context, Real horizon, bool carryGeometry,
                        std::vector<IslandContact>& contacts)
{
    const Real tolerance = context.settings.contactTolerance;
    const std::span<const Real> reach =
        islandReach(island, slots, context.settings.gravity, horizon);
    if (context.threads > 1) {
        findPairContactsOverThreads(island, slots, tolerance, reach, carryGeometry,
                                    context.threads, contacts);
    } else {
        contacts.clear();
        for (std::size_t k = 0; k < island.pairs.size(); ++k) {
            if (!findPairContact(island, slots, tolerance, reach, carryGeometry, k,
                                 contacts.emplace_back())) {
                contacts.pop_back();
            }
        }
    }
    addHalfSpaceContacts(island, slots, context, reach, context.threads, contacts);
}

} // namespace tumble
