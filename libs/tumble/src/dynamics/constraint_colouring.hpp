// Greedy colouring of constraints so no two in one colour move the same dynamic body; the
// constraints of one colour can then be solved in parallel (docs/physics/10-broad-phase.md,
// (10.5)).
#pragma once

#include "collision/broad_phase.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace tumble {

/// The most colours a colouring may use: one bit per colour in a 64-bit mask per body.
inline constexpr std::uint32_t kMaxConstraintColours = 64;

/// Constraints grouped by colour. Colour c < colourCount holds
/// constraints[offsets[c] .. offsets[c+1]); the overflow group, which no colour could take and
/// which is solved serially, follows at constraints[offsets[colourCount] .. offsets.back()).
struct ConstraintColours {
    /// Indices into the constraint span, ascending within each group.
    std::vector<std::uint32_t> constraints;
    /// colourCount + 2 entries.
    std::vector<std::uint32_t> offsets{0, 0};
    /// Colours used, the overflow group not counted.
    std::uint32_t colourCount = 0;

    std::span<const std::uint32_t> colour(std::size_t c) const
    {
        return std::span<const std::uint32_t>(constraints).subspan(offsets[c],
                                                                   offsets[c + 1] - offsets[c]);
    }

    std::span<const std::uint32_t> overflow() const { return colour(colourCount); }
};

/// Gives each constraint, in input order, the lowest of the first `maxColours` colours
/// (1..kMaxConstraintColours) that neither of its dynamic bodies has yet; a constraint for which
/// none is free goes to the overflow group (10.5). `constraints` hold body indices into
/// `isStatic`; static bodies may appear in any number of constraints of one colour. The result
/// depends only on the inputs. Pass island-local body indices to keep the per-body masks small.
ConstraintColours colourConstraints(std::span<const ProxyPair> constraints,
                                    std::span<const std::uint8_t> isStatic,
                                    std::uint32_t maxColours);

} // namespace tumble
