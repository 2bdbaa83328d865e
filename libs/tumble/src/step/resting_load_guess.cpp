// The weight carried down an island, as the first guess of new resting contacts (11.13).
#include "step/resting_load_guess.hpp"

#include <algorithm>
#include <numeric>

namespace tumble {

namespace {

/// A contact supports the body above it when its normal is within 60 degrees of up, n . up >=
/// 1/2: a steeper one holds a load mostly by friction, and its normal force L / (n . up) would
/// grow without bound (11.13).
constexpr Real kLeastUpright = 0.5;

/// n . up of a contact seen from `body`, with the normal turned to point into the body, for a
/// contact that supports it; zero for any other.
Real uprightness(const IslandContact& contact, std::uint32_t body, const Vec3& up)
{
    const Real sign = contact.solverB == body ? 1.0 : contact.solverA == body ? -1.0 : 0.0;
    const Real upright = sign * glm::dot(contact.manifold.normal, up);
    return upright >= kLeastUpright ? upright : 0.0;
}

/// The contacts of each of the island's bodies, by index into `contacts`.
std::vector<std::vector<std::uint32_t>> contactsOfBodies(std::span<const IslandContact> contacts,
                                                         std::size_t count)
{
    std::vector<std::vector<std::uint32_t>> of(count);
    for (std::uint32_t index = 0; index < contacts.size(); ++index) {
        for (const std::uint32_t body : {contacts[index].solverA, contacts[index].solverB}) {
            if (body < count) {
                of[body].push_back(index);
            }
        }
    }
    return of;
}

} // namespace

void guessRestingImpulses(const CoupledIsland& island, std::span<const BodySlot> slots,
                          std::span<const IslandContact> contacts,
                          std::span<ContactConstraint> constraints,
                          const std::vector<std::uint8_t>& guess, const Vec3& gravity, Real tau)
{
    const Real weightPerMass = glm::length(gravity);
    if (!(weightPerMass > 0.0)) {
        return;
    }
    const Vec3 up = -gravity / weightPerMass;
    const std::size_t count = island.bodies.size();
    // the load each body passes down, N: its own weight first
    std::vector<Real> load(count);
    std::vector<std::uint32_t> order(count);
    std::iota(order.begin(), order.end(), 0u);
    for (std::size_t i = 0; i < count; ++i) {
        load[i] = slots[island.bodies[i]].body.mass * weightPerMass;
    }
    const auto height = [&](std::uint32_t i) {
        return glm::dot(up, slots[island.bodies[i]].body.position);
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return height(a) > height(b); });
    const std::vector<std::vector<std::uint32_t>> contactsOf = contactsOfBodies(contacts, count);
    for (const std::uint32_t body : order) {
        // (11.13): the least-norm forces f_c = L u_c / sum u_c^2 over the contacts below
        // (u_c = n_c . up > 0) carry the load L, sum f_c u_c = L
        Real sumSquares = 0.0;
        for (const std::uint32_t index : contactsOf[body]) {
            const Real upright = uprightness(contacts[index], body, up);
            sumSquares += upright > 0.0 ? upright * upright : 0.0;
        }
        if (!(sumSquares > 0.0)) {
            continue;
        }
        for (const std::uint32_t index : contactsOf[body]) {
            const IslandContact& contact = contacts[index];
            const Real upright = uprightness(contact, body, up);
            if (!(upright > 0.0)) {
                continue;
            }
            const Real force = load[body] * upright / sumSquares;
            const std::uint32_t below =
                contact.solverB == body ? contact.solverA : contact.solverB;
            if (below < count) {
                load[below] += force * upright;
            }
            for (int k = 0; k < contact.manifold.pointCount; ++k) {
                const std::uint32_t point = contact.firstConstraint + static_cast<std::uint32_t>(k);
                if (guess[point] != 0) {
                    constraints[point].normalImpulse = force * tau / contact.manifold.pointCount;
                }
            }
        }
    }
}

} // namespace tumble
