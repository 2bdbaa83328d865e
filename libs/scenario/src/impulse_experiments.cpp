#include "tumble/scenario/impulse_experiments.hpp"

#include <algorithm>

namespace tumble::scenario {

std::vector<ImpulseExperiment> impulseExperiments(const Scenario& loaded,
                                                  const std::string& labelPrefix)
{
    std::vector<ImpulseExperiment> experiments;
    for (const ImpulseSpec& spec : loaded.impulses) {
        const auto body =
            std::find_if(loaded.bodies.begin(), loaded.bodies.end(),
                         [&](const BodySpec& candidate) { return candidate.name == spec.body; });
        if (body == loaded.bodies.end()) {
            continue;
        }
        // a file with one experiment is named by its task, several by task and body
        ImpulseExperiment experiment{
            .label = loaded.impulses.size() > 1 ? labelPrefix + ": " + spec.body : labelPrefix,
            .startVelocity = body->def.linearVelocity,
            .startAngularVelocity = body->def.angularVelocity,
            .targetVelocity = spec.targetVelocity,
            .targetAngularVelocity = spec.targetAngularVelocity,
            .impulse = spec.impulse.value_or(Vec3(0.0)),
            .offset = spec.offset.value_or(Vec3(0.0))};
        experiments.push_back(experiment);
    }
    return experiments;
}

} // namespace tumble::scenario
