// What a World keeps for each body besides the Body users see: the slot behind its id and the
// state the step carries from one step to the next.
#pragma once

#include "collision/pair_geometry_cache.hpp"
#include "step/kept_constraints.hpp"
#include "step/soft_kept_island.hpp"
#include "tumble/body.hpp"
#include "tumble/contact.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace tumble {

/// Last sub-step's impulses at one point of a contact of the island solver and the sub-step's
/// length, kept by the contact's owner (the lower dynamic body of two, or the dynamic one) for
/// warm starting (11.6).
struct CachedContactPoint {
    /// The other side: a body's slot index, or kPlaneSide + plane index, or kGroundSide.
    std::uint32_t other = 0;
    std::uint32_t id = 0;
    /// Where the point was, in the owner's body frame, m: a point whose features changed name
    /// without moving (a tie in the clipping) is found by it (11.6).
    Vec3 localPosition{0.0};
    Real normalImpulse = 0.0;
    Vec3 frictionImpulse{0.0};
    Real tau = 0.0;
};

/// Last step's impulses of one contact of the soft step (docs/physics/12-soft-step.md, (12.5)),
/// kept by the contact's owner as for CachedContactPoint: the normal impulse of each point by
/// its feature key, and the manifold's friction impulse (world frame) and twist impulse.
struct CachedSoftContact {
    std::uint32_t other = 0;
    int pointCount = 0;
    std::array<std::uint32_t, 4> ids{};
    /// Where each point was in the world when kept, m: a point whose features changed name
    /// without moving (a tie in the clipping) is found by it in the owner's frame, as in (11.6).
    std::array<Vec3, 4> positions{};
    std::array<Real, 4> normalImpulses{};
    Vec3 frictionImpulse{0.0};
    Real twistImpulse = 0.0;
};

/// Side keys of the static half-spaces in CachedContactPoint::other.
constexpr std::uint32_t kGroundSide = 0xffffffffu;
constexpr std::uint32_t kPlaneSide = 0x80000000u;

struct BodySlot {
    /// First, on the line of the body's kind and shape, which no step writes: the serial passes
    /// over every slot read them without fetching lines another thread's finish wrote.
    std::uint32_t generation = 0;
    bool alive = false;
    Body body;
    /// Whether any vertex touched the ground at the end of the last step.
    bool touchingGround = false;
    /// End of the first step of the current slow spell, s.
    Real slowSince = 0.0;
    /// Last step's resting-contact impulses, to warm-start the next.
    WarmStartCache warmStart{};
    /// Whether the body was solved with others (or with static geometry other than the ground)
    /// in the last step.
    bool coupled = false;
    /// Last step's impulses of the contacts this body owns in the island solver.
    std::vector<CachedContactPoint> contactCache;
    /// Last step's impulses of the soft step's contacts this body owns, and the body's pose when
    /// they were kept (their points' frame).
    std::vector<CachedSoftContact> softContacts;
    Transform softContactsPose{};
    /// The box-box geometry of the pairs this body owns: with another body of higher slot, or
    /// with a static body (9.11).
    PairGeometryCache pairGeometry;
    /// The constraints of the island this body was the lowest of in the last step (11.6a).
    KeptConstraints kept;
    /// The soft step's manifolds of the island this body was the lowest of (12.5b).
    SoftKeptIsland softKept;
};

} // namespace tumble
