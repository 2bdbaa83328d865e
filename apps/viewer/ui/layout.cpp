#include "viewer/ui/layout.hpp"

#include <algorithm>

namespace tumble::viewer::ui {
namespace {

/// The free part must be at least this big, pixels, or the panels are taken to cover it all.
constexpr float kMinFreeSide = 120.0f;

} // namespace

float leftWidth(float displayWidth) { return std::min(kLeftWidth, kLeftShare * displayWidth); }

float rightWidth(float displayWidth) { return std::min(kRightWidth, kRightShare * displayWidth); }

ViewRegion leftColumn(const glm::vec2& display)
{
    return {{kMargin, kMargin}, {kMargin + leftWidth(display.x), display.y - kMargin}};
}

ViewRegion rightColumn(const glm::vec2& display)
{
    return {{display.x - kMargin - rightWidth(display.x), kMargin},
            {display.x - kMargin, display.y - kMargin}};
}

ViewRegion logRegion(const glm::vec2& display)
{
    const float left = leftWidth(display.x) + 2.0f * kMargin;
    const float right = std::max(display.x - rightWidth(display.x) - 2.0f * kMargin, left + 200.0f);
    return {{left, display.y - kLogHeight - kMargin}, {right, display.y - kMargin}};
}

ViewRegion freeViewRegion(const glm::vec2& display)
{
    const ViewRegion log = logRegion(display);
    const ViewRegion free{{log.min.x, kMargin}, {log.max.x, log.min.y - kMargin}};
    if (free.size().x < kMinFreeSide || free.size().y < kMinFreeSide) {
        return {glm::vec2(0.0f), display};
    }
    return free;
}

} // namespace tumble::viewer::ui
