// PlotHistory: the last seconds of the selected body's height, speeds and energies, and the
// moments of its collisions, for the live plots.
#pragma once

#include "viewer/ring_buffer.hpp"

#include <utility>

namespace tumble::viewer {

/// What the plots show of one body at one moment (float: ImGui plots in float).
struct PlotSample {
    /// Simulated time, s.
    float time = 0.0f;
    /// Height of the centre of mass, m.
    float height = 0.0f;
    /// |v|, m/s.
    float speed = 0.0f;
    /// |w|, rad/s.
    float angularSpeed = 0.0f;
    /// Kinetic, potential and total energy, J.
    float kinetic = 0.0f;
    float potential = 0.0f;
    float total = 0.0f;
};

enum class PlotQuantity { Height, Speed, AngularSpeed, Kinetic, Potential, Total };

[[nodiscard]] float valueOf(const PlotSample& sample, PlotQuantity quantity);

/// Samples at most every `sampleInterval` seconds of simulated time, kept for `windowSeconds`,
/// and collision times over the same window. Time running backwards (a reset) clears it.
class PlotHistory {
public:
    /// Collision marks kept at most.
    static constexpr std::size_t kMaxCollisionMarks = 512;

    PlotHistory(double windowSeconds, double sampleInterval);

    /// Keeps `sample` unless it comes sooner than sampleInterval after the last one kept.
    void record(const PlotSample& sample);
    /// Marks a collision at `time`, s.
    void markCollision(float time);
    void clear();

    [[nodiscard]] const RingBuffer<PlotSample>& samples() const { return m_samples; }
    /// Collision times no older than the window before the newest sample, oldest first.
    [[nodiscard]] const RingBuffer<float>& collisions() const { return m_collisions; }
    [[nodiscard]] double windowSeconds() const { return m_windowSeconds; }
    /// Smallest and largest value of `quantity` over the samples kept ({0, 0} when empty).
    [[nodiscard]] std::pair<float, float> range(PlotQuantity quantity) const;

private:
    void dropOld(float newest);

    double m_windowSeconds;
    double m_sampleInterval;
    RingBuffer<PlotSample> m_samples;
    RingBuffer<float> m_collisions;
};

} // namespace tumble::viewer
