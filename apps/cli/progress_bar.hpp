// The one-line progress bar on stderr of the long commands (run, throw, validate), redrawn in
// place with a carriage return at most five times a second.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace tumble::cli {

class ProgressBar {
public:
    /// A bar over `total` units of work named `unit` ("steps", "throws"); `shownTotal` is what
    /// the bar counts up to when this is one of several equal blocks (MPI ranks).
    ProgressBar(std::int64_t total, std::int64_t shownTotal, std::string unit);

    /// Redraws when 0.2 s have passed since the last time (or when forced).
    void update(std::int64_t done, bool force = false);

    /// Clears the line so the report starts on a clean one.
    static void clear();

private:
    using Clock = std::chrono::steady_clock;

    std::int64_t m_total;
    double m_scale;
    std::string m_unit;
    Clock::time_point m_start;
    Clock::time_point m_lastDraw;
};

} // namespace tumble::cli
