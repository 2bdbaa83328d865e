// Scenario files: TOML text (plus --set overrides) checked against the schema and turned into a
// plain Scenario. docs/scenario-format.md is the user-facing description of every key.
#include "tumble/scenario/scenario.hpp"

#include "overrides.hpp"
#include "read_entries.hpp"
#include "read_throw.hpp"
#include "schema.hpp"
#include "toml_reader.hpp"
#include "vector_length.hpp"

#include <toml++/toml.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

namespace tumble::scenario {

namespace {

using detail::ifPresent;
using detail::TomlReader;

/// world.solver and the soft step's keys (docs/physics/12-soft-step.md).
void readSoftSettings(const TomlReader& reader, const toml::table& world, WorldSettings& settings)
{
    ifPresent(world, "solver", [&](const toml::node& node) {
        const std::size_t index = reader.choice(node, "world.solver", detail::kSolverNames);
        settings.solver = index == 0 ? ContactSolver::Exact : ContactSolver::Soft;
    });
    ifPresent(world, "soft_substeps", [&](const toml::node& node) {
        const long long substeps = reader.integer(node, "world.soft_substeps");
        if (substeps < 1 || substeps > 64) {
            reader.fail(node, "world.soft_substeps",
                        "must be between 1 and 64, got " + std::to_string(substeps));
        }
        settings.softSubsteps = static_cast<int>(substeps);
    });
    ifPresent(world, "soft_contact_hertz", [&](const toml::node& node) {
        settings.softContactHertz = reader.positive(node, "world.soft_contact_hertz");
    });
    ifPresent(world, "soft_damping_ratio", [&](const toml::node& node) {
        settings.softDampingRatio = reader.nonNegative(node, "world.soft_damping_ratio");
    });
    ifPresent(world, "soft_push_speed", [&](const toml::node& node) {
        settings.softPushSpeed = reader.positive(node, "world.soft_push_speed");
    });
}

/// world.integrator, world.response and the other WorldSettings keys.
void readSettings(const TomlReader& reader, const toml::table& world, WorldSettings& settings)
{
    ifPresent(world, "gravity", [&](const toml::node& node) {
        settings.gravity = reader.vec3(node, "world.gravity");
        reader.checkRange(node, "world.gravity", detail::vectorLength(settings.gravity),
                          detail::kGravityRange, "the length ");
    });
    ifPresent(world, "integrator", [&](const toml::node& node) {
        const std::size_t index = reader.choice(node, "world.integrator", detail::kIntegratorNames);
        settings.integrator = index == 0 ? Integrator::Exact : Integrator::Handout;
    });
    ifPresent(world, "response", [&](const toml::node& node) {
        const std::size_t index = reader.choice(node, "world.response", detail::kResponseNames);
        settings.response = index == 0 ? ContactResponse::Sequential : ContactResponse::Average;
    });
    ifPresent(world, "contact_tolerance", [&](const toml::node& node) {
        settings.contactTolerance = reader.positive(node, "world.contact_tolerance");
        reader.checkRange(node, "world.contact_tolerance", settings.contactTolerance,
                          detail::kContactToleranceRange);
    });
    ifPresent(world, "restitution_threshold", [&](const toml::node& node) {
        settings.restitutionThreshold = reader.nonNegative(node, "world.restitution_threshold");
    });
    ifPresent(world, "solver_iterations", [&](const toml::node& node) {
        const long long iterations = reader.integer(node, "world.solver_iterations");
        if (iterations < 1 || iterations > 1'000'000) {
            reader.fail(node, "world.solver_iterations",
                        "must be between 1 and 1000000, got " + std::to_string(iterations));
        }
        settings.solverIterations = static_cast<int>(iterations);
    });
    readSoftSettings(reader, world, settings);
    ifPresent(world, "sleep", [&](const toml::node& node) {
        settings.allowSleep = reader.boolean(node, "world.sleep");
    });
    ifPresent(world, "sleep_linear_speed", [&](const toml::node& node) {
        settings.sleepLinearSpeed = reader.nonNegative(node, "world.sleep_linear_speed");
    });
    ifPresent(world, "sleep_angular_speed", [&](const toml::node& node) {
        settings.sleepAngularSpeed = reader.nonNegative(node, "world.sleep_angular_speed");
    });
    ifPresent(world, "sleep_time", [&](const toml::node& node) {
        settings.sleepTime = reader.positive(node, "world.sleep_time");
    });
}

void readWorld(const TomlReader& reader, const toml::table& world, Scenario& scenario)
{
    reader.checkKeys(world, "world", detail::kWorldKeys);
    ifPresent(world, "dt", [&](const toml::node& node) {
        scenario.dt = reader.positive(node, "world.dt");
        reader.checkRange(node, "world.dt", scenario.dt, detail::kDtRange);
    });
    ifPresent(world, "duration", [&](const toml::node& node) {
        scenario.duration = reader.positive(node, "world.duration");
    });
    // A run of more steps than the range allows would never end in practice.
    if (const toml::node* node = world.get("duration") ? world.get("duration") : world.get("dt")) {
        reader.checkRange(*node, "world.duration", scenario.duration / scenario.dt,
                          detail::kStepCountRange, "the number of steps duration / dt ");
    }
    readSettings(reader, world, scenario.settings);
}

Plane readGround(const TomlReader& reader, const toml::table& ground)
{
    reader.checkKeys(ground, "ground", detail::kGroundKeys);
    Plane plane{};
    ifPresent(ground, "height",
              [&](const toml::node& node) {
                  plane.height = reader.real(node, "ground.height");
                  reader.checkRange(node, "ground.height", plane.height, detail::kGroundHeightRange);
              });
    return plane;
}

Scenario readScenario(const TomlReader& reader, const toml::table& root)
{
    reader.checkKeys(root, "", detail::kTopLevelKeys);
    Scenario scenario;
    scenario.sourceName = reader.sourceName();
    ifPresent(root, "world", [&](const toml::node& node) {
        readWorld(reader, reader.table(node, "world", "a table ([world])"), scenario);
    });
    ifPresent(root, "ground", [&](const toml::node& node) {
        const toml::table& ground = reader.table(node, "ground", "a table ([ground])");
        scenario.ground = readGround(reader, ground);
        scenario.groundMaterial = detail::readOptionalMaterial(reader, ground, "ground");
    });
    detail::readPlanes(reader, root, scenario);
    detail::readBodies(reader, root, scenario);
    detail::readSpawns(reader, root, scenario);
    if (scenario.bodies.empty()) {
        const toml::node* bodies = root.get("body");
        throw ScenarioError(bodies == nullptr ? SourceLocation{reader.sourceName(), 0}
                                              : reader.locate(*bodies),
                            "body", "a scenario needs at least one [[body]] or [[spawn]]");
    }
    detail::readImpulses(reader, root, scenario);
    detail::readThrow(reader, root, scenario);
    return scenario;
}

} // namespace

Scenario parseScenario(std::string_view text, std::string_view sourceName,
                       std::span<const std::string> overrides)
{
    const TomlReader reader{std::string(sourceName)};
    toml::table root;
    try {
        root = toml::parse(text, sourceName);
    } catch (const toml::parse_error& error) {
        throw ScenarioError(
            SourceLocation{std::string(sourceName), static_cast<int>(error.source().begin.line)},
            "", "TOML syntax error: " + std::string(error.description()));
    }
    detail::applyOverrides(root, overrides);
    return readScenario(reader, root);
}

Scenario loadScenario(const std::filesystem::path& path, std::span<const std::string> overrides)
{
    const std::string name = path.string();
    std::error_code status;
    if (std::filesystem::is_directory(path, status)) {
        throw ScenarioError(SourceLocation{name, 0}, "", "cannot read scenario: is a directory");
    }
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        throw ScenarioError(SourceLocation{name, 0}, "",
                            std::string("cannot open scenario: ") + std::strerror(errno));
    }
    std::ostringstream text;
    text << file.rdbuf();
    if (file.bad()) {
        throw ScenarioError(SourceLocation{name, 0}, "", "cannot read scenario: read failed");
    }
    return parseScenario(text.str(), name, overrides);
}

} // namespace tumble::scenario
