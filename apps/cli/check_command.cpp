#include "check_command.hpp"

#include "console.hpp"

#include "tumble/scenario/runner.hpp"
#include "tumble/scenario/scenario.hpp"

#include <iostream>
#include <optional>

namespace tumble::cli {
namespace {

std::string counted(std::size_t count, const char* singular, const char* plural)
{
    return std::to_string(count) + " " + (count == 1 ? singular : plural);
}

/// Whether a target can be reached depends on the body's velocity when it acts, so the scene is
/// simulated (silently) up to the last target impulse; Runner::step throws if one is unreachable.
void checkTargets(const scenario::Scenario& loaded)
{
    std::optional<Real> lastTarget;
    for (const scenario::ImpulseSpec& spec : loaded.impulses) {
        if (spec.isTarget() && spec.at < loaded.duration) {
            lastTarget = spec.at;
        }
    }
    if (!lastTarget) {
        return;
    }
    // one step past it, as an impulse just before a step boundary acts at that boundary
    scenario::Runner runner(loaded);
    while (runner.time() <= *lastTarget + loaded.dt) {
        runner.step();
    }
}

} // namespace

CLI::App* addCheckCommand(CLI::App& app, CheckOptions& options)
{
    CLI::App* command = app.add_subcommand("check", "Validate a scenario file without running it");
    command->add_option("FILE", options.file, "Scenario file (TOML)")->required()->type_name("");
    command->add_option("--set", options.overrides, "Override a scenario value, KEY=VALUE; repeatable")
        ->type_name("KEY=VALUE")
        ->allow_extra_args(false);
    return command;
}

int checkCommand(const CheckOptions& options)
{
    const scenario::Scenario loaded = scenario::loadScenario(options.file, options.overrides);
    // building the world catches what only the engine can (it asserts on bad bodies)
    scenario::buildWorld(loaded);
    checkTargets(loaded);
    // what run would say about the file: impulses it never reaches (the runner applies one within
    // 1e-9 dt of a step's start in that step)
    const Real lastApplied = loaded.duration - 1e-9 * loaded.dt;
    for (const scenario::ImpulseSpec& spec : loaded.impulses) {
        if (spec.at >= lastApplied) {
            std::cout << "note: " << spec.label << " at t = " << formatFixed(spec.at)
                      << " s is after the end of the run and would not be applied\n";
        }
    }
    std::cout << options.file << ": ok (" << counted(loaded.bodies.size(), "body", "bodies") << ", "
              << counted(loaded.impulses.size(), "impulse", "impulses") << ", dt=" << loaded.dt
              << ", duration=" << loaded.duration << ")\n";
    return kExitOk;
}

} // namespace tumble::cli
