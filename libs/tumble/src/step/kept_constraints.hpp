// An island's contact constraints kept from one step to the next while nothing they are made of
// has moved: the rows and effective masses are not prepared again and the impulses are not
// matched again (docs/physics/11-island-solver.md, (11.6a)).
#pragma once

#include "collision/pair_manifold.hpp"
#include "dynamics/contact_constraint.hpp"
#include "tumble/math.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace tumble {

struct BodySlot;
struct CoupledIsland;
struct IslandContact;

/// (11.6a): the kept rows stand while each contact point is within this distance (m) of where it
/// was when they were prepared, and its normal within this angle (rad); the bodies' poses within
/// (9.11) of theirs.
inline constexpr Real kKeptPointDistance = 1e-8;
inline constexpr Real kKeptNormalAngle = 1e-9;

/// What one dynamic body's rows depend on: its pose, inverse mass and size.
struct KeptBodyInput {
    Transform pose{};
    Real invMass = 0.0;
    Vec3 size{0.0};
};

/// What one contact's rows depend on besides its bodies: its sides and its manifold.
struct KeptContactInput {
    std::uint32_t sideA = 0;
    std::uint32_t sideB = 0;
    PairManifold manifold{};
};

/// The constraints of the last step of the island whose lowest body keeps them, with what they
/// were prepared from. Valid only after a step of one sub-step: the impulses are those of its
/// solve, over `tau`.
struct KeptConstraints {
    bool valid = false;
    Real tau = 0.0;
    std::vector<std::uint32_t> bodies;
    std::vector<KeptBodyInput> bodyInputs;
    std::vector<KeptContactInput> contactInputs;
    std::vector<ContactConstraint> constraints;

    /// Gives back the memory of constraints no island uses any more.
    void release()
    {
        if (bodies.capacity() != 0 || constraints.capacity() != 0) {
            *this = KeptConstraints{};
        }
    }
};

/// Each of these spreads its work over `threads` threads, with the same result for any number.

/// Whether `kept` holds constraints prepared for this island's bodies and `contacts` (the same
/// contacts in the same order, each with the same sides and point ids, the points in any order)
/// with every input still within (11.6a) of its value then.
bool keptConstraintsHold(const KeptConstraints& kept, const CoupledIsland& island,
                         std::span<const BodySlot> slots, std::span<const IslandContact> contacts,
                         int threads = 1);

/// Records the inputs the island's constraints are being prepared from now; `kept` stays invalid
/// until a step that prepared them ends after one sub-step.
void recordKeptInputs(KeptConstraints& kept, const CoupledIsland& island,
                      std::span<const BodySlot> slots, std::span<const IslandContact> contacts,
                      int threads = 1);

/// Sets the kept constraints to the contacts found now (those keptConstraintsHold accepted): each
/// contact's first constraint, its points in the order found now, each point's gap and the
/// pair's material.
void refreshKeptConstraints(KeptConstraints& kept, std::span<IslandContact> contacts,
                            int threads = 1);

} // namespace tumble
