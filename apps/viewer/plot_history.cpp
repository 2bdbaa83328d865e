#include "viewer/plot_history.hpp"

#include <algorithm>
#include <cmath>

namespace tumble::viewer {
namespace {

/// A sample this close (as a fraction of the interval) to the next due time is due, so samples
/// every step of an interval that is a whole number of steps are not skipped by rounding.
constexpr double kIntervalSlack = 1e-3;

} // namespace

float valueOf(const PlotSample& sample, PlotQuantity quantity)
{
    switch (quantity) {
    case PlotQuantity::Height:
        return sample.height;
    case PlotQuantity::Speed:
        return sample.speed;
    case PlotQuantity::AngularSpeed:
        return sample.angularSpeed;
    case PlotQuantity::Kinetic:
        return sample.kinetic;
    case PlotQuantity::Potential:
        return sample.potential;
    case PlotQuantity::Total:
        return sample.total;
    }
    return 0.0f;
}

PlotHistory::PlotHistory(double windowSeconds, double sampleInterval)
    : m_windowSeconds(windowSeconds), m_sampleInterval(sampleInterval),
      m_samples(static_cast<std::size_t>(std::ceil(windowSeconds / sampleInterval)) + 2),
      m_collisions(kMaxCollisionMarks)
{
}

void PlotHistory::record(const PlotSample& sample)
{
    if (!m_samples.empty()) {
        const float last = m_samples.back().time;
        if (sample.time < last) {
            clear();
        } else if (sample.time - last < m_sampleInterval * (1.0 - kIntervalSlack)) {
            return;
        }
    }
    m_samples.push(sample);
    dropOld(sample.time);
}

void PlotHistory::markCollision(float time)
{
    if (!m_collisions.empty() && time < m_collisions.back()) {
        m_collisions.clear();
    }
    m_collisions.push(time);
    dropOld(time);
}

void PlotHistory::clear()
{
    m_samples.clear();
    m_collisions.clear();
}

std::pair<float, float> PlotHistory::range(PlotQuantity quantity) const
{
    if (m_samples.empty()) {
        return {0.0f, 0.0f};
    }
    float low = valueOf(m_samples[0], quantity);
    float high = low;
    for (std::size_t i = 1; i < m_samples.size(); ++i) {
        const float value = valueOf(m_samples[i], quantity);
        low = std::min(low, value);
        high = std::max(high, value);
    }
    return {low, high};
}

void PlotHistory::dropOld(float newest)
{
    const auto oldest = static_cast<float>(newest - m_windowSeconds);
    m_samples.dropWhile([&](const PlotSample& sample) { return sample.time < oldest; });
    m_collisions.dropWhile([&](float time) { return time < oldest; });
}

} // namespace tumble::viewer
