#include "viewer/scene_bounds.hpp"

#include "tumble/scenario/runner.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace tumble::viewer {

namespace {

/// Samples of the run taken when framing it.
constexpr long long kFramingSamples = 200;

std::optional<float> groundOf(const scenario::Scenario& scenario)
{
    if (!scenario.ground) {
        return std::nullopt;
    }
    return static_cast<float>(scenario.ground->height);
}

/// The bounding sphere's radius of a cuboid: half its diagonal.
float radiusOf(const Vec3& size) { return static_cast<float>(0.5 * glm::length(size)); }

} // namespace

ViewBounds sceneBounds(const scenario::Scenario& scenario)
{
    std::vector<glm::vec3> centres;
    std::vector<float> radii;
    for (const scenario::BodySpec& body : scenario.bodies) {
        centres.emplace_back(body.def.position);
        radii.push_back(radiusOf(body.def.shape.size));
    }
    return boundsOf(centres, radii, groundOf(scenario));
}

ViewBounds runBounds(const scenario::Scenario& scenario)
{
    std::vector<glm::vec3> centres;
    std::vector<float> radii;
    scenario::Runner runner(scenario);
    const auto sample = [&] {
        for (const BodyId id : runner.bodies()) {
            const Body& body = runner.world().body(id);
            if (isFinite(body.position)) {
                centres.emplace_back(body.position);
                radii.push_back(radiusOf(body.shape.size));
            }
        }
    };
    const double seconds = std::min(scenario.duration, kFramedSeconds);
    const long long steps =
        std::min(static_cast<long long>(std::ceil(seconds / scenario.dt)), kFramedSteps);
    const long long every = std::max(1LL, steps / kFramingSamples);
    sample();
    // a target impulse out of reach ends the run where it is
    try {
        for (long long step = 1; step <= steps; ++step) {
            runner.step();
            if (step % every == 0 || step == steps) {
                sample();
            }
        }
    } catch (const scenario::ScenarioError&) {
        sample();
    }
    return boundsOf(centres, radii, groundOf(scenario));
}

float referenceGridHeight(const scenario::Scenario& scenario)
{
    float lowest = 0.0f;
    for (std::size_t i = 0; i < scenario.bodies.size(); ++i) {
        const scenario::BodySpec& body = scenario.bodies[i];
        const auto bottom =
            static_cast<float>(body.def.position.y - 0.5 * glm::length(body.def.shape.size));
        lowest = i == 0 ? bottom : std::min(lowest, bottom);
    }
    return lowest - 1.0f;
}

} // namespace tumble::viewer
