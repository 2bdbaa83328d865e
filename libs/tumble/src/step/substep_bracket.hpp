// The bracket of a sub-step re-solved after a time-of-impact search
// (docs/physics/04-detection.md, (4.3a)).
#pragma once

#include "tumble/math.hpp"

#include <cmath>
#include <limits>

namespace tumble {

/// (4.3a): the sub-step's length between the longest known to be clear and the shortest known
/// to cross, each with the end height above the aim of the lowest free vertex under its own
/// re-solved motion, and the next length to try: false position on that height, with the
/// Illinois halving (an end kept twice in a row has its height halved, so the other end cannot
/// stall), or the midpoint where the heights do not straddle the aim (a vertex that dips below
/// the plane and comes back up within the crossing sub-step).
class SubstepBracket {
public:
    /// The search stops once the clear and the crossing lengths agree to this fraction.
    static constexpr Real kResolution = 1e-9;

    void markClear(Real length, Real heightAboveAim)
    {
        m_clear = length;
        m_clearHeight = heightAboveAim;
        if (m_lastMoved > 0) {
            m_crossingHeight *= 0.5;
        }
        m_lastMoved = 1;
    }

    void markCrossing(Real length, Real heightAboveAim)
    {
        m_crossing = length;
        m_crossingHeight = heightAboveAim;
        if (m_lastMoved < 0) {
            m_clearHeight *= 0.5;
        }
        m_lastMoved = -1;
    }

    [[nodiscard]] Real clear() const { return m_clear; }
    [[nodiscard]] bool hasCrossing() const { return std::isfinite(m_crossing); }
    [[nodiscard]] bool closed() const { return m_crossing - m_clear <= kResolution * m_crossing; }

    [[nodiscard]] Real next() const
    {
        if (m_clearHeight > 0.0 && m_crossingHeight < 0.0) {
            const Real interpolated = m_clear + (m_crossing - m_clear) * m_clearHeight /
                                                    (m_clearHeight - m_crossingHeight);
            if (interpolated > m_clear && interpolated < m_crossing) {
                return interpolated;
            }
        }
        return 0.5 * (m_clear + m_crossing);
    }

private:
    Real m_clear = 0.0;
    Real m_crossing = std::numeric_limits<Real>::infinity();
    Real m_clearHeight = 0.0;
    Real m_crossingHeight = 0.0;
    /// +1 when the clear end moved last, -1 the crossing end, 0 neither yet.
    int m_lastMoved = 0;
};

} // namespace tumble
