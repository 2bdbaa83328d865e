#include "viewer/impulse_experiments.hpp"

#include "tumble/scenario/scenario.hpp"

#include <algorithm>

namespace tumble::viewer {

std::vector<ImpulseExperiment> loadImpulseExperiments(const std::filesystem::path& directory)
{
    std::vector<ImpulseExperiment> experiments;
    for (const ExperimentFile& file : kExperimentFiles) {
        scenario::Scenario loaded;
        try {
            loaded = scenario::loadScenario(directory / file.fileName);
        } catch (const scenario::ScenarioError&) {
            continue;
        }
        // a file with one experiment is named by its task, several by task and body
        for (const scenario::ImpulseSpec& spec : loaded.impulses) {
            const auto body = std::find_if(
                loaded.bodies.begin(), loaded.bodies.end(),
                [&](const scenario::BodySpec& candidate) { return candidate.name == spec.body; });
            if (body == loaded.bodies.end()) {
                continue;
            }
            ImpulseExperiment experiment;
            experiment.label = file.label;
            if (loaded.impulses.size() > 1) {
                experiment.label += ": " + spec.body;
            }
            experiment.startVelocity = body->def.linearVelocity;
            experiment.startAngularVelocity = body->def.angularVelocity;
            experiment.targetVelocity = spec.targetVelocity;
            experiment.targetAngularVelocity = spec.targetAngularVelocity;
            experiment.impulse = spec.impulse.value_or(Vec3(0.0));
            experiment.offset = spec.offset.value_or(Vec3(0.0));
            experiments.push_back(experiment);
        }
    }
    return experiments;
}

} // namespace tumble::viewer
