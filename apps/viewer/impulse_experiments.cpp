#include "viewer/impulse_experiments.hpp"

#include "tumble/scenario/scenario.hpp"

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
        const std::vector<ImpulseExperiment> found =
            scenario::impulseExperiments(loaded, file.label);
        experiments.insert(experiments.end(), found.begin(), found.end());
    }
    return experiments;
}

} // namespace tumble::viewer
