// FixedStepAccumulator: turns real frame times into a whole number of fixed simulation steps, so
// the simulation never sees the frame time as its dt.
#pragma once

namespace tumble::viewer {

/// Real time (scaled for slow motion) accumulates; each fixed step consumes dt of it. A backlog
/// larger than maxStepsPerFrame steps is dropped, so a slow frame makes the simulation fall
/// behind real time for a moment instead of spiralling into ever longer frames.
class FixedStepAccumulator {
public:
    /// Frame times longer than this count as this long (a stall, a debugger stop), s.
    static constexpr double kMaxFrameSeconds = 0.25;

    FixedStepAccumulator(double dt, int maxStepsPerFrame);

    /// Adds `frameSeconds` x `timeScale` of simulated time; returns the number of steps due now.
    int advance(double frameSeconds, double timeScale);
    /// Simulated time waiting for the next step, s (in [0, dt)).
    [[nodiscard]] double pending() const { return m_pending; }
    /// True when the last advance dropped time because too many steps were due.
    [[nodiscard]] bool fellBehind() const { return m_fellBehind; }
    [[nodiscard]] double dt() const { return m_dt; }
    /// Changes the step and drops the pending time.
    void setDt(double dt);
    /// Drops the pending time.
    void reset();

private:
    double m_dt;
    int m_maxStepsPerFrame;
    double m_pending = 0.0;
    bool m_fellBehind = false;
};

} // namespace tumble::viewer
