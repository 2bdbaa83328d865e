// Greedy constraint-graph colouring with a colour mask per body (docs/physics/10-broad-phase.md,
// (10.5); Catto, Box2D v3 "Solver2D" and "SIMD matters" notes on graph colouring).
#include "dynamics/constraint_colouring.hpp"

#include "tumble_assert.hpp"

#include <algorithm>
#include <bit>

namespace tumble {

ConstraintColours colourConstraints(std::span<const ProxyPair> constraints,
                                    std::span<const std::uint8_t> isStatic,
                                    std::uint32_t maxColours)
{
    TUMBLE_ASSERT(maxColours >= 1 && maxColours <= kMaxConstraintColours);
    const std::uint64_t allowed =
        maxColours == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << maxColours) - 1;
    const std::uint32_t overflowColour = maxColours;

    // each constraint to the lowest colour free at both its dynamic ends (10.5)
    std::vector<std::uint64_t> coloursOfBody(isStatic.size(), 0);
    std::vector<std::uint32_t> colourOf(constraints.size());
    std::vector<std::uint32_t> groupSizes(maxColours + 1, 0);
    std::uint32_t colourCount = 0;
    for (std::size_t i = 0; i < constraints.size(); ++i) {
        const ProxyPair& constraint = constraints[i];
        TUMBLE_ASSERT(constraint.a < isStatic.size() && constraint.b < isStatic.size());
        const bool movesA = !isStatic[constraint.a];
        const bool movesB = !isStatic[constraint.b];
        const std::uint64_t taken = (movesA ? coloursOfBody[constraint.a] : 0) |
                                    (movesB ? coloursOfBody[constraint.b] : 0);
        const std::uint64_t available = allowed & ~taken;
        std::uint32_t colour = overflowColour;
        if (available != 0) {
            colour = static_cast<std::uint32_t>(std::countr_zero(available));
            const std::uint64_t bit = std::uint64_t{1} << colour;
            coloursOfBody[constraint.a] |= movesA ? bit : 0;
            coloursOfBody[constraint.b] |= movesB ? bit : 0;
            colourCount = std::max(colourCount, colour + 1);
        }
        colourOf[i] = colour;
        ++groupSizes[colour];
    }

    // group by colour (colours are used from the lowest, so 0 .. colourCount-1 are all in use),
    // the overflow group last; a counting sort keeps input order within each group
    ConstraintColours result;
    result.colourCount = colourCount;
    result.offsets.assign(colourCount + 2, 0);
    for (std::uint32_t c = 0; c < colourCount; ++c) {
        result.offsets[c + 1] = result.offsets[c] + groupSizes[c];
    }
    result.offsets[colourCount + 1] = result.offsets[colourCount] + groupSizes[overflowColour];
    result.constraints.resize(constraints.size());
    std::vector<std::uint32_t> next(result.offsets.begin(), result.offsets.end() - 1);
    for (std::size_t i = 0; i < constraints.size(); ++i) {
        const std::uint32_t group = colourOf[i] == overflowColour ? colourCount : colourOf[i];
        result.constraints[next[group]++] = static_cast<std::uint32_t>(i);
    }
    return result;
}

} // namespace tumble
