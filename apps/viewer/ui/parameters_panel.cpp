// The parameters panel: gravity, dt, integrator and response model for the world; mass, size,
// elasticity and friction for the selected body. Edits act on the running world at once (dt at
// the next reset) and are kept for reset; reload drops them.
#include "viewer/ui/panels.hpp"

#include "tumble/material.hpp"

#include <imgui.h>

#include <algorithm>

namespace tumble::viewer::ui {
namespace {

/// Smallest mass and size the fields accept (the world requires positive values).
constexpr double kMinPositive = 1e-3;

bool inputVec3(const char* label, Vec3& value, const char* format = "%.3f")
{
    return ImGui::InputScalarN(label, ImGuiDataType_Double, &value.x, 3, nullptr, nullptr, format,
                               ImGuiInputTextFlags_EnterReturnsTrue);
}

void drawWorld(SimRunner& sim)
{
    const scenario::Scenario& scenario = sim.scenario();

    Vec3 gravity = scenario.settings.gravity;
    if (inputVec3("gravity, m/s^2", gravity)) {
        sim.setGravity(gravity);
    }

    int integrator = scenario.settings.integrator == Integrator::Exact ? 0 : 1;
    if (ImGui::Combo("integrator", &integrator, "exact\0handout\0")) {
        sim.setIntegrator(integrator == 0 ? Integrator::Exact : Integrator::Handout);
    }
    int response = scenario.settings.response == ContactResponse::Sequential ? 0 : 1;
    if (ImGui::Combo("response", &response, "sequential\0average\0")) {
        sim.setResponse(response == 0 ? ContactResponse::Sequential : ContactResponse::Average);
    }

    // dt changes the step count of the run, so it waits for the next reset
    double dt = scenario.dt;
    const double minDt = 1e-5;
    const double maxDt = 0.05;
    if (ImGui::SliderScalar("dt, s", ImGuiDataType_Double, &dt, &minDt, &maxDt, "%.6f",
                            ImGuiSliderFlags_Logarithmic)) {
        sim.setDt(dt);
    }
    if (scenario.dt != sim.runner().scenario().dt) {
        ImGui::TextDisabled("new dt applies at reset (R)");
    }
}

void drawBody(ViewerState& state)
{
    SimRunner& sim = state.sim;
    const std::size_t index = state.settings.selectedBody;
    const BodyDef& def = sim.scenario().bodies.at(index).def;

    double mass = def.mass;
    if (ImGui::InputDouble("mass, kg", &mass, 0.1, 1.0, "%.3f",
                           ImGuiInputTextFlags_EnterReturnsTrue)) {
        sim.setMass(index, std::max(mass, kMinPositive));
    }
    Vec3 size = def.shape.size;
    if (inputVec3("size, m", size)) {
        sim.setSize(index, glm::max(size, Vec3(kMinPositive)));
    }

    Material material = def.material;
    const double zero = 0.0;
    const double one = 1.0;
    const double maxFriction = 2.0;
    bool changed = ImGui::SliderScalar("elasticity", ImGuiDataType_Double, &material.restitution,
                                       &zero, &one, "%.3f");
    changed |= ImGui::SliderScalar("friction", ImGuiDataType_Double, &material.friction, &zero,
                                   &maxFriction, "%.3f");
    if (changed) {
        // a static coefficient, when the file gives one, may not fall below the kinetic one
        if (material.staticFriction) {
            material.staticFriction = std::max(*material.staticFriction, material.friction);
        }
        sim.setMaterial(index, material);
    }
    ImGui::TextDisabled("the inspector's inverse inertia follows mass and size");
}

} // namespace

void drawParameters(ViewerState& state)
{
    ImGui::PushItemWidth(-110.0f);
    drawWorld(state.sim);
    ImGui::Separator();
    drawBodySelector(state);
    if (state.sim.bodyCount() > 0) {
        drawBody(state);
    }
    ImGui::PopItemWidth();
}

} // namespace tumble::viewer::ui
