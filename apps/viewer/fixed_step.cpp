#include "viewer/fixed_step.hpp"

#include <algorithm>
#include <cmath>

namespace tumble::viewer {
namespace {

/// Pending time within this fraction of dt of a whole step counts as the whole step, so that
/// four frames of 1/240 s make four steps despite rounding.
constexpr double kStepSlack = 1e-9;

} // namespace

FixedStepAccumulator::FixedStepAccumulator(double dt, int maxStepsPerFrame)
    : m_dt(dt), m_maxStepsPerFrame(std::max(maxStepsPerFrame, 1))
{
}

int FixedStepAccumulator::advance(double frameSeconds, double timeScale)
{
    const double frame = std::clamp(frameSeconds, 0.0, kMaxFrameSeconds);
    m_pending += frame * std::max(timeScale, 0.0);

    // whole steps due, then what is left of a step
    const double due = std::floor(m_pending / m_dt + kStepSlack);
    m_fellBehind = due > m_maxStepsPerFrame;
    if (m_fellBehind) {
        m_pending = 0.0;
        return m_maxStepsPerFrame;
    }
    m_pending = std::max(m_pending - due * m_dt, 0.0);
    return static_cast<int>(due);
}

void FixedStepAccumulator::setDt(double dt)
{
    m_dt = dt;
    reset();
}

void FixedStepAccumulator::reset()
{
    m_pending = 0.0;
    m_fellBehind = false;
}

} // namespace tumble::viewer
