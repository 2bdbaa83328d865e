// The body inspector: position, orientation, v, w, L, energies, inverse inertia (body and world
// frame), and the contact with the ground (vertex, edge or face, and the touching vertices).
#include "viewer/ui/panels.hpp"

#include "viewer/palette.hpp"

#include "tumble/contact.hpp"
#include "tumble/shape.hpp"

#include <imgui.h>

#include <cmath>
#include <string>

namespace tumble::viewer::ui {
namespace {

/// `value` as printed with `decimals` decimals, with values that would print as -0 made +0.
double shown(Real value, int decimals)
{
    return std::fabs(value) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : value;
}

void row(const char* label, const Vec3& value, const char* unit)
{
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(label);
    ImGui::TableNextColumn();
    ImGui::Text("% .4f % .4f % .4f  %s", shown(value.x, 4), shown(value.y, 4), shown(value.z, 4),
                unit);
}

void row(const char* label, Real value, const char* unit)
{
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(label);
    ImGui::TableNextColumn();
    ImGui::Text("% .6f  %s", shown(value, 6), unit);
}

void matrixRows(const char* label, const Mat3& m)
{
    // printed by rows; glm stores columns, m[column][row]
    for (int r = 0; r < 3; ++r) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(r == 0 ? label : "");
        ImGui::TableNextColumn();
        ImGui::Text("% .4f % .4f % .4f", shown(m[0][r], 4), shown(m[1][r], 4), shown(m[2][r], 4));
    }
}

void faceSwatch(CuboidFace face)
{
    const glm::vec3 colour = palette::faceColour(face);
    ImGui::ColorButton(faceName(face), ImVec4(colour.r, colour.g, colour.b, 1.0f),
                       ImGuiColorEditFlags_NoTooltip, ImVec2(12.0f, 12.0f));
    ImGui::SameLine();
    ImGui::Text("%s", faceName(face));
}

void drawContact(const ContactManifold& contacts)
{
    if (contacts.pointCount == 0) {
        ImGui::TextDisabled("not touching the ground");
        return;
    }
    ImGui::Text("touching on %s %s (%d %s)",
                contacts.feature() == ContactFeature::Edge ? "an" : "a",
                featureName(contacts.feature()), contacts.pointCount,
                contacts.pointCount == 1 ? "vertex" : "vertices");
    for (int i = 0; i < contacts.pointCount; ++i) {
        const ContactPoint& point = contacts.points[static_cast<std::size_t>(i)];
        ImGui::Text("  vertex %d: % .4f % .4f % .4f", point.vertex, shown(point.position.x, 4),
                    shown(point.position.y, 4), shown(point.position.z, 4));
    }
    const Vec3 average = contacts.averagePoint();
    ImGui::Text("  average:  % .4f % .4f % .4f", shown(average.x, 4), shown(average.y, 4),
                shown(average.z, 4));
}

} // namespace

void drawBodySelector(ViewerState& state)
{
    const SimRunner& sim = state.sim;
    if (sim.bodyCount() < 2) {
        return;
    }
    const std::string current = sim.runner().bodyName(state.settings.selectedBody);
    if (ImGui::BeginCombo("body", current.c_str())) {
        for (std::size_t i = 0; i < sim.bodyCount(); ++i) {
            if (ImGui::Selectable(sim.runner().bodyName(i).c_str(), i == state.settings.selectedBody) &&
                i != state.settings.selectedBody) {
                // the plots start over with the new body
                state.settings.selectedBody = i;
                state.plots.clear();
            }
        }
        ImGui::EndCombo();
    }
}

void drawInspector(ViewerState& state)
{
    const SimRunner& sim = state.sim;
    if (sim.bodyCount() == 0) {
        ImGui::TextDisabled("the scenario has no bodies");
        return;
    }
    drawBodySelector(state);
    const std::size_t index = state.settings.selectedBody;
    const Body& body = sim.body(index);
    const Vec3& gravity = sim.world().settings().gravity;
    const Real kinetic = body.kineticEnergy();
    const Real potential = body.potentialEnergy(gravity);

    ImGui::Text("%s: %.3f kg, %.3g x %.3g x %.3g m%s", sim.runner().bodyName(index).c_str(),
                body.mass, body.shape.size.x, body.shape.size.y, body.shape.size.z,
                body.asleep ? ", at rest" : "");
    if (ImGui::BeginTable("state", 2, ImGuiTableFlags_SizingFixedFit)) {
        row("position", body.position, "m");
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("orientation");
        ImGui::TableNextColumn();
        ImGui::Text("w % .4f  (% .4f % .4f % .4f)", shown(body.orientation.w, 4),
                    shown(body.orientation.x, 4), shown(body.orientation.y, 4),
                    shown(body.orientation.z, 4));
        row("v", body.linearVelocity, "m/s");
        row("w", body.angularVelocity, "rad/s");
        row("L", body.angularMomentum(), "kg m^2/s");
        row("kinetic", kinetic, "J");
        row("potential", potential, "J");
        row("total", kinetic + potential, "J");
        const Vec3& inv = body.invInertiaBody;
        const Mat3 invBody(Vec3(inv.x, 0.0, 0.0), Vec3(0.0, inv.y, 0.0), Vec3(0.0, 0.0, inv.z));
        matrixRows("I^-1 body", invBody);
        matrixRows("I^-1 world", body.invInertiaWorld);
        ImGui::EndTable();
    }

    // which face is down, with its colour, so the picture and the numbers can be matched
    ImGui::TextUnformatted("face down:");
    ImGui::SameLine();
    faceSwatch(faceAlong(body.orientation, -Plane::normal()));
    drawContact(sim.world().contactsOf(sim.runner().bodies()[index]));
}

} // namespace tumble::viewer::ui
