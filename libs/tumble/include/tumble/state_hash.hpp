// A hash of the state of a world's bodies, for comparing runs bit for bit (determinism checks,
// `tumble run --hash`).
#pragma once

#include "tumble/body_id.hpp"
#include "tumble/math.hpp"
#include "tumble/world.hpp"

#include <bit>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

namespace tumble {

/// FNV-1a, 64 bits: offset basis and prime.
inline constexpr std::uint64_t kFnvOffsetBasis = 14695981039346656037ull;
inline constexpr std::uint64_t kFnvPrime = 1099511628211ull;

/// Mixes the 8 bytes of `value`'s IEEE 754 bit pattern, least significant byte first (so the
/// hash does not depend on the machine's byte order), into the FNV-1a hash `hash`.
inline std::uint64_t fnv1aMix(std::uint64_t hash, Real value)
{
    const auto bits = std::bit_cast<std::uint64_t>(value);
    for (int byte = 0; byte < 8; ++byte) {
        hash ^= (bits >> (8 * byte)) & 0xffu;
        hash *= kFnvPrime;
    }
    return hash;
}

/// FNV-1a 64 over, for each body in the given order: position (x, y, z), orientation (w, x, y,
/// z), velocity (x, y, z) and angular velocity (x, y, z). Equal hashes mean bit-identical states
/// (up to the hash's collisions); +0 and -0 hash differently.
inline std::uint64_t stateHash(const World& world, std::span<const BodyId> bodies)
{
    std::uint64_t hash = kFnvOffsetBasis;
    for (const BodyId id : bodies) {
        const Body& body = world.body(id);
        const Quat& q = body.orientation;
        for (const Real value :
             {body.position.x, body.position.y, body.position.z, q.w, q.x, q.y, q.z,
              body.linearVelocity.x, body.linearVelocity.y, body.linearVelocity.z,
              body.angularVelocity.x, body.angularVelocity.y, body.angularVelocity.z}) {
            hash = fnv1aMix(hash, value);
        }
    }
    return hash;
}

/// The same over every live body, in creation order (World::bodyIds).
inline std::uint64_t stateHash(const World& world)
{
    const std::vector<BodyId> ids = world.bodyIds();
    return stateHash(world, ids);
}

} // namespace tumble
