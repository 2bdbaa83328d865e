#include "progress_bar.hpp"

#include <cstdio>

namespace tumble::cli {

namespace {

/// Seconds between redraws.
constexpr double kRedrawInterval = 0.2;
constexpr int kBarWidth = 30;

} // namespace

ProgressBar::ProgressBar(std::int64_t total, std::int64_t shownTotal, std::string unit)
    : m_total(total),
      m_scale(static_cast<double>(shownTotal) / static_cast<double>(total > 0 ? total : 1)),
      m_unit(std::move(unit)), m_start(Clock::now()), m_lastDraw(m_start)
{
}

void ProgressBar::update(std::int64_t done, bool force)
{
    const Clock::time_point now = Clock::now();
    if (!force && std::chrono::duration<double>(now - m_lastDraw).count() < kRedrawInterval) {
        return;
    }
    m_lastDraw = now;
    const double elapsed = std::chrono::duration<double>(now - m_start).count();
    const double fraction =
        m_total > 0 ? static_cast<double>(done) / static_cast<double>(m_total) : 1.0;
    const double rate = elapsed > 0.0 ? static_cast<double>(done) * m_scale / elapsed : 0.0;
    const double left = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    char bar[kBarWidth + 1];
    const int filled = static_cast<int>(fraction * kBarWidth);
    for (int i = 0; i < kBarWidth; ++i) {
        bar[i] = i < filled ? '#' : '.';
    }
    bar[kBarWidth] = '\0';
    std::fprintf(stderr, "\r[%s] %lld/%lld %s  %.0f %s/s  %.1f s left  ", bar,
                 static_cast<long long>(static_cast<double>(done) * m_scale),
                 static_cast<long long>(static_cast<double>(m_total) * m_scale), m_unit.c_str(),
                 rate, m_unit.c_str(), left);
    std::fflush(stderr);
}

void ProgressBar::clear()
{
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
}

} // namespace tumble::cli
