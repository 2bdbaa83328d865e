// Eight rows of eight doubles turned into eight columns with vector shuffles, for the lane
// passes' gathers and scatters of eight bodies at once (docs/physics/12-soft-step.md, (12.9)):
// eight loads and 24 shuffles where lane-by-lane inserts take 48 loads and about as many
// inserts. Data movement only: no bit of a result depends on it.
#pragma once

#include "dynamics/vector_lanes.hpp"

namespace tumble::lanes {

/// Whether rows and columns are turned by shuffles here: eight lanes, with GCC's
/// __builtin_shuffle; elsewhere the passes insert and extract lane by lane.
#if defined(__GNUC__) && !defined(__clang__) && TUMBLE_VECTOR_LANES == 8
#define TUMBLE_TRANSPOSE_BY_SHUFFLES 1
#else
#define TUMBLE_TRANSPOSE_BY_SHUFFLES 0
#endif

#if TUMBLE_TRANSPOSE_BY_SHUFFLES
/// m[i][j] becomes m[j][i] (an 8 x 8 matrix of doubles, one row a vector): three rounds of
/// shuffles, each pairing rows one, two and four apart.
TUMBLE_WIDE_INLINE void transposeEight(Wide (&m)[8])
{
    using Index = Mask;
    const Index evens{0, 8, 2, 10, 4, 12, 6, 14};
    const Index odds{1, 9, 3, 11, 5, 13, 7, 15};
    const Index lowPairs{0, 1, 8, 9, 4, 5, 12, 13};
    const Index highPairs{2, 3, 10, 11, 6, 7, 14, 15};
    const Index lowHalves{0, 1, 2, 3, 8, 9, 10, 11};
    const Index highHalves{4, 5, 6, 7, 12, 13, 14, 15};
    Wide a[8];
    for (int i = 0; i < 4; ++i) {
        a[i] = __builtin_shuffle(m[2 * i], m[2 * i + 1], evens);
        a[4 + i] = __builtin_shuffle(m[2 * i], m[2 * i + 1], odds);
    }
    // a[i]: rows 2i, 2i+1 at the even columns; a[4+i]: at the odd ones
    Wide b[8];
    for (int half = 0; half < 2; ++half) {
        for (int odd = 0; odd < 2; ++odd) {
            const Wide& first = a[4 * odd + 2 * half];
            const Wide& second = a[4 * odd + 2 * half + 1];
            b[4 * half + 2 * odd] = __builtin_shuffle(first, second, lowPairs);
            b[4 * half + 2 * odd + 1] = __builtin_shuffle(first, second, highPairs);
        }
    }
    // b[4h + 2o + p]: rows 4h..4h+3 at the columns 4c + 2p + o, c = 0, 1
    for (int column = 0; column < 4; ++column) {
        const int odd = column % 2;
        const int pair = column / 2;
        m[column] = __builtin_shuffle(b[2 * odd + pair], b[4 + 2 * odd + pair], lowHalves);
        m[column + 4] = __builtin_shuffle(b[2 * odd + pair], b[4 + 2 * odd + pair], highHalves);
    }
}
#endif

} // namespace tumble::lanes
