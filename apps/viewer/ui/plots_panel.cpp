// The live plots: height, speed, angular speed and the energies of the selected body over the
// last seconds, each collision marked by a vertical line.
#include "viewer/ui/panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <vector>

namespace tumble::viewer::ui {
namespace {

constexpr float kPlotHeight = 62.0f;
constexpr ImU32 kFrameColour = IM_COL32(20, 22, 28, 220);
constexpr ImU32 kCollisionColour = IM_COL32(255, 90, 80, 150);
constexpr ImU32 kLabelColour = IM_COL32(200, 200, 200, 255);

struct Series {
    PlotQuantity quantity;
    const char* name;
    ImU32 colour;
};

/// Smallest and largest value of all the series, padded so that flat lines sit mid-plot.
std::pair<float, float> yRange(const PlotHistory& history, std::initializer_list<Series> series)
{
    float low = 0.0f;
    float high = 0.0f;
    bool first = true;
    for (const Series& s : series) {
        const auto [seriesLow, seriesHigh] = history.range(s.quantity);
        low = first ? seriesLow : std::min(low, seriesLow);
        high = first ? seriesHigh : std::max(high, seriesHigh);
        first = false;
    }
    const float pad = std::max(0.05f * (high - low), 1e-3f);
    return {low - pad, high + pad};
}

void drawPlot(const char* title, const char* unit, const PlotHistory& history,
              std::initializer_list<Series> series)
{
    const auto& samples = history.samples();

    // the legend: each series' name and latest value in its colour
    ImGui::TextUnformatted(title);
    for (const Series& s : series) {
        ImGui::SameLine();
        float latest = samples.empty() ? 0.0f : valueOf(samples.back(), s.quantity);
        // what would print as -0.000 prints as 0.000
        latest = std::fabs(latest) < 5e-4f ? 0.0f : latest;
        ImGui::PushStyleColor(ImGuiCol_Text, s.colour);
        ImGui::Text("%s %.3f", s.name, static_cast<double>(latest));
        ImGui::PopStyleColor();
    }
    ImGui::SameLine();
    ImGui::TextDisabled("%s", unit);

    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const ImVec2 size(ImGui::GetContentRegionAvail().x, kPlotHeight);
    ImGui::Dummy(size);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), kFrameColour);
    if (samples.empty()) {
        return;
    }

    // all the samples kept: the start of the run stretched over the width, then the last
    // `window` seconds scrolling
    const float start = samples.front().time;
    const float span = std::max(samples.back().time - start, 1e-3f);
    const auto [low, high] = yRange(history, series);
    const auto toScreen = [&](float time, float value) {
        return ImVec2(origin.x + (time - start) / span * size.x,
                      origin.y + (1.0f - (value - low) / (high - low)) * size.y);
    };

    for (std::size_t i = 0; i < history.collisions().size(); ++i) {
        const float x = toScreen(history.collisions()[i], 0.0f).x;
        draw->AddLine(ImVec2(x, origin.y), ImVec2(x, origin.y + size.y), kCollisionColour);
    }
    std::vector<ImVec2> points(samples.size());
    for (const Series& s : series) {
        for (std::size_t i = 0; i < samples.size(); ++i) {
            points[i] = toScreen(samples[i].time, valueOf(samples[i], s.quantity));
        }
        draw->AddPolyline(points.data(), static_cast<int>(points.size()), s.colour, 0, 1.5f);
    }

    char label[32];
    std::snprintf(label, sizeof label, "%.3g", static_cast<double>(high));
    draw->AddText(ImVec2(origin.x + 3.0f, origin.y + 1.0f), kLabelColour, label);
    std::snprintf(label, sizeof label, "%.3g", static_cast<double>(low));
    draw->AddText(ImVec2(origin.x + 3.0f, origin.y + size.y - ImGui::GetFontSize() - 1.0f),
                  kLabelColour, label);
}

} // namespace

void drawPlots(ViewerState& state)
{
    const PlotHistory& history = state.plots;
    ImGui::TextDisabled("last %.0f s; red lines: collisions", history.windowSeconds());
    drawPlot("height", "m", history, {{PlotQuantity::Height, "y", IM_COL32(120, 200, 255, 255)}});
    drawPlot("speed", "m/s, rad/s", history,
             {{PlotQuantity::Speed, "|v|", IM_COL32(130, 230, 130, 255)},
              {PlotQuantity::AngularSpeed, "|w|", IM_COL32(230, 120, 230, 255)}});
    drawPlot("energy", "J", history,
             {{PlotQuantity::Kinetic, "K", IM_COL32(255, 170, 80, 255)},
              {PlotQuantity::Potential, "U", IM_COL32(120, 200, 255, 255)},
              {PlotQuantity::Total, "E", IM_COL32(240, 240, 240, 255)}});
}

} // namespace tumble::viewer::ui
