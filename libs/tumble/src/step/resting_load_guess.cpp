// The weight carried down an island, as the first guess of new resting contacts (11.13).
#include "step/resting_load_guess.hpp"

#include <algorithm>
#include <numeric>

namespace tumble {

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
    for (const std::uint32_t body : order) {
        // the contacts below the body: their normal, turned to point into the body, points up
        Real uprightness = 0.0;
        for (const IslandContact& contact : contacts) {
            const Real sign = contact.solverB == body ? 1.0 : contact.solverA == body ? -1.0 : 0.0;
            uprightness += std::max(0.0, sign * glm::dot(contact.manifold.normal, up));
        }
        if (!(uprightness > 0.0)) {
            continue;
        }
        for (const IslandContact& contact : contacts) {
            const Real sign = contact.solverB == body ? 1.0 : contact.solverA == body ? -1.0 : 0.0;
            const Real upright = sign * glm::dot(contact.manifold.normal, up);
            if (!(upright > 0.0)) {
                continue;
            }
            // this contact's share of the vertical load, and the normal force that carries it
            const Real share = load[body] * upright / uprightness;
            const Real force = share / upright;
            const std::uint32_t below = sign > 0.0 ? contact.solverA : contact.solverB;
            if (below < count) {
                load[below] += share;
            }
            for (int k = 0; k < contact.manifold.pointCount; ++k) {
                const std::uint32_t index = contact.firstConstraint + static_cast<std::uint32_t>(k);
                if (guess[index] != 0) {
                    constraints[index].normalImpulse = force * tau / contact.manifold.pointCount;
                }
            }
        }
    }
}

} // namespace tumble
