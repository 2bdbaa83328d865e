// ViewerSettings: the plain state the panels and keys edit (what to show, which body, the
// impulse tool's inputs). The loop, the scene builder and the renderer read it.
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <string>

namespace tumble::viewer {

/// What the impulse tool's fields hold.
struct ImpulseToolInputs {
    /// An impulse (N s) and its offset from the centre of mass (world axes, m).
    glm::vec3 impulse{0.0f, 0.0f, 0.0f};
    glm::vec3 offset{0.0f, 0.0f, 0.0f};
    /// A target velocity (m/s) and angular velocity (rad/s) to solve for.
    glm::vec3 targetVelocity{0.0f, 0.0f, 0.0f};
    glm::vec3 targetAngularVelocity{0.0f, 0.0f, 0.0f};
    /// Leave the angular velocity as it is (the target names only a velocity).
    bool keepAngularVelocity = false;
    /// Whether an experiment button first gives the body the experiment's starting velocities.
    bool startFromExperiment = true;
    /// What the last button did: the impulse and offset applied, or why a target is out of reach.
    std::string lastResult;
};

struct ViewerSettings {
    /// Scenario index of the body the inspector, plots and follow mode use.
    std::size_t selectedBody = 0;
    /// Keep the camera's target on the selected body.
    bool followBody = false;
    bool showAxes = false;
    bool showAngularVelocity = false;
    bool showAngularMomentum = false;
    /// Touching vertices and their average.
    bool showContacts = true;
    /// The last collision's normal and friction impulses.
    bool showImpulses = true;
    bool showShadow = true;
    /// The ImGui panels (off: the 3D view alone, as in capture with --no-ui).
    bool showUi = true;
    /// Arrow length per unit of impulse, m per N s.
    float impulseScale = 0.15f;
    /// Arrow length per unit of angular velocity (rad/s) or angular momentum (kg m^2/s), m.
    float vectorScale = 0.5f;
    ImpulseToolInputs impulseTool{};
};

} // namespace tumble::viewer
