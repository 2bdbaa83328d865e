// Anderson acceleration of the Gauss-Seidel sweeps of a solve at one cuboid's vertices
// (docs/physics/05-normal-impulse.md, (5.14)).
#pragma once

#include "body_state.hpp"
#include "dynamics/solver_point.hpp"
#include "tumble/body.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

namespace tumble {

/// The depth-two fit of (5.14) falls back to depth one when the two residual differences are
/// this close to parallel (det <= this times the product of their squared lengths).
inline constexpr Real kAndersonConditioning = 1e-10;

/// Every impulse of a solve, three per point: normal, tangent 1, tangent 2.
using ImpulseVector = std::array<Real, 24>;

/// (5.14): Anderson acceleration of depth two over the sweeps (Anderson 1965; Walker & Ni 2011).
/// A sweep is a map x -> G(x) of the impulses, and on a die's contact it contracts by a steady
/// factor of 0.3 to 0.9 a sweep. From the last three sweeps' images g and residuals f = G(x) - x
/// the next iterate is g_k - dG gamma, with gamma the least-squares fit of the residual
/// differences dF to f_k: exact for a linear map with two dominant modes, and a plain sweep
/// again (the history dropped) whenever a sweep fails to shrink the residual, as at a change of
/// which points push or slide. Only the iterate moves: every solve still ends on a sweep of its
/// own that met the convergence test, or on (5.11) at the cap.
class SweepAccelerator {
public:
    /// Keeps x_k, the impulses before the sweep.
    void recordStart(std::span<const SolverPoint> points)
    {
        m_size = 3 * points.size();
        for (std::size_t i = 0; i < points.size(); ++i) {
            m_start[3 * i] = points[i].normalImpulse;
            m_start[3 * i + 1] = points[i].tangentImpulse1;
            m_start[3 * i + 2] = points[i].tangentImpulse2;
        }
    }

    /// Moves the impulses (and the body with them) from the sweep's image to the extrapolation.
    void extrapolate(Body& body, const SolverFrame& frame, std::span<SolverPoint> points)
    {
        ImpulseVector& image = m_images[m_newest ^ 1];
        ImpulseVector& residual = m_residuals[m_newest ^ 1];
        Real residualNorm = 0.0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            image[3 * i] = points[i].normalImpulse;
            image[3 * i + 1] = points[i].tangentImpulse1;
            image[3 * i + 2] = points[i].tangentImpulse2;
        }
        for (std::size_t j = 0; j < m_size; ++j) {
            residual[j] = image[j] - m_start[j];
            residualNorm = std::max(residualNorm, std::abs(residual[j]));
        }
        if (!(residualNorm < m_residualNorm)) {
            m_depth = 0;
        }
        Real gamma1 = 0.0;
        Real gamma2 = 0.0;
        if (fit(residual, gamma1, gamma2)) {
            const ImpulseVector& image1 = m_images[m_newest];
            const ImpulseVector& image2 = m_images[2];
            for (std::size_t i = 0; i < points.size(); ++i) {
                std::array<Real, 3> next{};
                for (std::size_t c = 0; c < 3; ++c) {
                    const std::size_t j = 3 * i + c;
                    next[c] = image[j] - gamma1 * (image[j] - image1[j]);
                    if (m_depth >= 2) {
                        next[c] -= gamma2 * (image1[j] - image2[j]);
                    }
                }
                SolverPoint& point = points[i];
                next[0] = std::max(0.0, next[0]);
                applyImpulseAtOffset(body,
                                     (next[0] - point.normalImpulse) * frame.n +
                                         (next[1] - point.tangentImpulse1) * frame.t1 +
                                         (next[2] - point.tangentImpulse2) * frame.t2,
                                     point.r);
                point.normalImpulse = next[0];
                point.tangentImpulse1 = next[1];
                point.tangentImpulse2 = next[2];
            }
        }
        // The newest becomes the middle entry, the middle one the oldest (slot 2).
        if (m_depth >= 1) {
            std::copy_n(m_images[m_newest].begin(), m_size, m_images[2].begin());
            std::copy_n(m_residuals[m_newest].begin(), m_size, m_residuals[2].begin());
        }
        m_newest ^= 1;
        m_residualNorm = residualNorm;
        m_depth = std::min(m_depth + 1, 2);
    }

private:
    /// The least-squares gamma of depth m_depth (two if its normal equations are well
    /// conditioned, else one); false when there is no history to fit.
    bool fit(const ImpulseVector& residual, Real& gamma1, Real& gamma2) const
    {
        if (m_depth == 0) {
            return false;
        }
        const ImpulseVector& residual1 = m_residuals[m_newest];
        const ImpulseVector& residual2 = m_residuals[2];
        Real a11 = 0.0;
        Real a12 = 0.0;
        Real a22 = 0.0;
        Real b1 = 0.0;
        Real b2 = 0.0;
        for (std::size_t j = 0; j < m_size; ++j) {
            const Real d1 = residual[j] - residual1[j];
            const Real d2 = m_depth >= 2 ? residual1[j] - residual2[j] : 0.0;
            a11 += d1 * d1;
            a12 += d1 * d2;
            a22 += d2 * d2;
            b1 += d1 * residual[j];
            b2 += d2 * residual[j];
        }
        const Real determinant = a11 * a22 - a12 * a12;
        if (m_depth >= 2 && determinant > kAndersonConditioning * a11 * a22) {
            gamma1 = (a22 * b1 - a12 * b2) / determinant;
            gamma2 = (a11 * b2 - a12 * b1) / determinant;
            return true;
        }
        if (a11 > 0.0) {
            gamma1 = b1 / a11;
            return true;
        }
        return false;
    }

    /// Not initialised (a solve that converges in a sweep or two, most of them, would pay for
    /// zeroing a kilobyte): only the first m_size entries are used, each written first, and the
    /// slot-2 entries only at depth two, after the copy that fills them.
    ImpulseVector m_start;
    /// Images and residuals of the last sweeps: m_newest (0 or 1) holds the last, slot 2 the one
    /// before; the other of 0 and 1 receives the sweep in hand.
    std::array<ImpulseVector, 3> m_images;
    std::array<ImpulseVector, 3> m_residuals;
    std::size_t m_size = 0;
    Real m_residualNorm = std::numeric_limits<Real>::infinity();
    int m_newest = 0;
    int m_depth = 0;
};

} // namespace tumble
