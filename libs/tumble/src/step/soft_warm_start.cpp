// The soft step's warm start (docs/physics/12-soft-step.md, (12.5)).
#include "step/soft_warm_start.hpp"

#include "parallel_for.hpp"
#include "prefetch.hpp"

#include <algorithm>
#include <vector>

namespace tumble {

namespace {

/// (11.6): how far, in contact tolerances, a point may be from a kept point of its contact whose
/// features had another name and still take its impulse.
constexpr Real kWarmStartReach = 10.0;
/// What of an owner's cache is asked for ahead: its first two contacts.
constexpr std::size_t kPrefetchedCacheBytes = 2 * sizeof(CachedSoftContact);

Vec3 inBodyFrame(const Vec3& position, const Quat& orientation, const Vec3& point)
{
    return glm::conjugate(orientation) * (point - position);
}

/// The kept point each of the contact's points takes its normal impulse from, or -1: the same
/// feature key first, then the nearest unclaimed kept point within `reach` in the owner's
/// frame, now and (`keptPose`) when kept.
std::array<int, 4> matchPoints(const IslandContact& contact, const CachedSoftContact& kept,
                               const Body& owner, const Transform& keptPose, Real reach)
{
    std::array<int, 4> match{-1, -1, -1, -1};
    std::array<bool, 4> taken{};
    const int count = contact.manifold.pointCount;
    for (int k = 0; k < count; ++k) {
        for (int j = 0; j < kept.pointCount; ++j) {
            if (!taken[j] && kept.ids[j] == contact.manifold.points[k].id) {
                match[k] = j;
                taken[j] = true;
                break;
            }
        }
    }
    for (int k = 0; k < count; ++k) {
        if (match[k] >= 0) {
            continue;
        }
        const Vec3 local =
            inBodyFrame(owner.position, owner.orientation, contact.manifold.points[k].position);
        Real nearest = reach * reach;
        for (int j = 0; j < kept.pointCount; ++j) {
            const Vec3 keptLocal =
                inBodyFrame(keptPose.position, keptPose.orientation, kept.positions[j]);
            const Real distance = lengthSquared(local - keptLocal);
            if (!taken[j] && distance <= nearest) {
                nearest = distance;
                match[k] = j;
            }
        }
        if (match[k] >= 0) {
            taken[match[k]] = true;
        }
    }
    return match;
}

} // namespace

KeptImpulses keptImpulsesOf(const CoupledIsland& island, std::span<const BodySlot> slots,
                            const IslandContact& contact, Real tolerance)
{
    KeptImpulses impulses;
    const BodySlot& slot = slots[island.bodies[contact.owner]];
    const std::vector<CachedSoftContact>& cache = slot.softContacts;
    const auto kept = std::find_if(cache.begin(), cache.end(), [&](const CachedSoftContact& c) {
        return c.other == contact.ownerKey;
    });
    if (kept == cache.end()) {
        return impulses;
    }
    // the owner's contacts come in the order they were kept: the next one's is asked for
    if (kept + 1 != cache.end()) {
        prefetchLines(&*(kept + 1), sizeof(CachedSoftContact));
    }
    const std::array<int, 4> match = matchPoints(contact, *kept, slot.body, slot.softContactsPose,
                                                 kWarmStartReach * tolerance);
    impulses.found = true;
    for (int k = 0; k < contact.manifold.pointCount; ++k) {
        if (match[k] >= 0) {
            impulses.normalImpulses[k] = kept->normalImpulses[match[k]];
        }
    }
    impulses.frictionImpulse = kept->frictionImpulse;
    impulses.twistImpulse = kept->twistImpulse;
    return impulses;
}

void prefetchKeptImpulses(const CoupledIsland& island, std::span<const BodySlot> slots,
                          std::span<const IslandContact> contacts, std::size_t k)
{
    if (k >= contacts.size() || (k > 0 && contacts[k].owner == contacts[k - 1].owner)) {
        return;
    }
    const std::uint32_t owner = island.bodies[contacts[k].owner];
    const std::vector<CachedSoftContact>& cache = slots[owner].softContacts;
    if (!cache.empty()) {
        prefetchLines(cache.data(), kPrefetchedCacheBytes);
    }
}

void startFromKept(const KeptImpulses& kept, SoftManifold& m)
{
    if (!kept.found) {
        return;
    }
    for (int k = 0; k < m.pointCount; ++k) {
        m.points[k].normalImpulse = kept.normalImpulses[k];
    }
    m.frictionImpulse1 = glm::dot(m.tangent1, kept.frictionImpulse);
    m.frictionImpulse2 = glm::dot(m.tangent2, kept.frictionImpulse);
    m.twistImpulse = kept.twistImpulse;
}

void storeSoftWarmStart(const CoupledIsland& island, std::span<BodySlot> slots,
                        std::span<const IslandContact> contacts,
                        std::span<const SoftContactResult> results,
                        std::span<const std::uint32_t> resultOf, int threads, std::size_t split,
                        std::span<const Vec3> centres, std::span<const Quat> orientations)
{
    const std::size_t bodies = island.bodies.size();
    const auto shares = static_cast<std::size_t>(std::max(1, threads));
    // each owner's cache is written by one share: with a split, the thread that finishes the
    // owner's half (12.9), else every shares-th owner
    const bool halves = split > 0 && split < bodies && shares >= 2;
    const auto shareOf = [&](std::uint32_t owner) {
        return halves ? (owner < split ? 0 : 1) : owner % shares;
    };
    // each share reads the owners from a table of their own, not from every contact, and
    // writes its owners' contacts in the narrow phase's order (owner after owner, as the next
    // step reads them)
    thread_local std::vector<std::uint32_t> keptOwners;
    std::vector<std::uint32_t>& owners = keptOwners;
    owners.resize(contacts.size());
    parallelFor(contacts.size(), threads, [&](std::size_t k) { owners[k] = contacts[k].owner; });
    parallelFor(shares, threads, [&](std::size_t share) {
        for (std::uint32_t local = 0; local < bodies; ++local) {
            if (shareOf(local) == share) {
                slots[island.bodies[local]].softContacts.clear();
            }
        }
        for (std::size_t index = 0; index < contacts.size(); ++index) {
            if (shareOf(owners[index]) != share) {
                continue;
            }
            const IslandContact& contact = contacts[index];
            const SoftContactResult& result = results[resultOf[index]];
            BodySlot& slot = slots[island.bodies[contact.owner]];
            if (slot.softContacts.empty()) {
                slot.softContactsPose =
                    centres.empty()
                        ? Transform{slot.body.position, slot.body.orientation}
                        : Transform{centres[contact.owner], orientations[contact.owner]};
            }
            // built where it is kept: a temporary is a cleared copy more
            CachedSoftContact& kept = slot.softContacts.emplace_back();
            kept.other = contact.ownerKey;
            kept.pointCount = result.pointCount;
            for (int k = 0; k < result.pointCount; ++k) {
                kept.ids[k] = contact.manifold.points[k].id;
                kept.positions[k] = contact.manifold.points[k].position;
                kept.normalImpulses[k] = result.normalImpulses[k];
            }
            kept.frictionImpulse = result.frictionImpulse;
            kept.twistImpulse = result.twistImpulse;
        }
    });
}

} // namespace tumble
