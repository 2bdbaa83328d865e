// The [[spawn]] array of a scenario file: many bodies from one seeded description, checked at
// load time like [[body]] entries and expanded into BodySpecs.
#include "read_entries.hpp"

#include "messages.hpp"
#include "schema.hpp"
#include "vector_length.hpp"

#include "tumble/scenario/random_draws.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tumble::scenario::detail {

namespace {

/// A spawn places at most this many bodies: a million cuboids is already a minute per simulated
/// second on one core.
inline constexpr ValidRange kSpawnCountRange{"spawn.count", 1.0, 1e6, "bodies"};

/// [low, high] with low <= high, both finite.
std::pair<Real, Real> readInterval(const TomlReader& reader, const toml::node& node,
                                   const std::string& key)
{
    const toml::array* array = node.as_array();
    if (array == nullptr || array->size() != 2) {
        reader.fail(node, key, "expected [low, high], got " + describeNode(node));
    }
    const Real low = reader.real(*array->get(0), key + "[0]");
    const Real high = reader.real(*array->get(1), key + "[1]");
    if (low > high) {
        reader.fail(node, key,
                    "low must not exceed high, got [" + formatReal(low) + ", " + formatReal(high) +
                        "]");
    }
    return {low, high};
}

/// Distance from the centre to a corner: no vertex of the cuboid is farther from its centre
/// whatever its orientation.
Real boundingRadius(const Cuboid& shape) { return 0.5 * glm::length(shape.size); }

SpawnSpec readSpawn(const TomlReader& reader, const toml::table& table, std::size_t index,
                    const Scenario& scenario)
{
    const std::string key = "spawn[" + std::to_string(index) + "]";
    reader.checkKeys(table, key, kSpawnKeys);
    const std::string context = " (" + key + ")";
    SpawnSpec spawn;
    spawn.where = reader.locate(table);
    const toml::node* count = table.get("count");
    if (count == nullptr) {
        reader.fail(table, key + ".count", "missing: the number of bodies to place");
    }
    const long long countValue = reader.integer(*count, key + ".count");
    reader.checkRange(*count, key + ".count", static_cast<Real>(countValue), kSpawnCountRange);
    spawn.count = static_cast<std::size_t>(countValue);
    ifPresent(table, "seed", [&](const toml::node& node) {
        const long long seed = reader.integer(node, key + ".seed");
        if (seed < 0) {
            reader.fail(node, key + ".seed", "must be >= 0, got " + std::to_string(seed));
        }
        spawn.seed = static_cast<std::uint64_t>(seed);
    });
    BodyDef& body = spawn.body;
    readShape(reader, table, key, context, body);
    ifPresent(table, "mass", [&](const toml::node& node) {
        body.mass = reader.positive(node, key + ".mass", context);
        reader.checkRange(node, key + ".mass", body.mass, kMassRange, {}, context);
    });
    // By default neighbours are one corner-to-corner diagonal apart, so no two can overlap.
    spawn.spacing = 2.0 * boundingRadius(body.shape);
    ifPresent(table, "spacing", [&](const toml::node& node) {
        spawn.spacing = reader.positive(node, key + ".spacing", context);
        // bodies touch each other, so grid neighbours closer than the diagonal could start
        // inside each other, whatever orientations are drawn
        if (spawn.count > 1 && spawn.spacing < 2.0 * boundingRadius(body.shape)) {
            reader.fail(node, key + ".spacing",
                        "must be at least the body's diagonal " +
                            formatReal(2.0 * boundingRadius(body.shape)) +
                            " m, got " + formatReal(spawn.spacing) +
                            ": neighbours could start inside each other" + context);
        }
        // neighbours farther apart than the valid positions cannot both lie within them; checked
        // on the value as written, before the farthest corner is computed from it
        if (spawn.count > 1) {
            reader.checkRange(node, key + ".spacing", spawn.spacing, kPositionRange,
                              "the distance between neighbours ", context);
        }
    });
    const toml::node* height = table.get("height");
    if (height == nullptr) {
        reader.fail(table, key + ".height",
                    "missing: [low, high], the range of centre-of-mass heights above the ground");
    }
    std::tie(spawn.heightLow, spawn.heightHigh) = readInterval(reader, *height, key + ".height");
    // Without a ground nothing can be inside it; with one, a body spawned lower than its
    // bounding radius could start partly below the plane.
    if (scenario.ground && spawn.heightLow < boundingRadius(body.shape)) {
        reader.fail(*height, key + ".height",
                    "the lowest height " + formatReal(spawn.heightLow) +
                        " m is less than the half diagonal " +
                        formatReal(boundingRadius(body.shape)) +
                        " m: a body could start inside the ground");
    }
    ifPresent(table, "orientation", [&](const toml::node& node) {
        if (const auto text = node.value<std::string>()) {
            if (*text != "random") {
                reader.fail(node, key + ".orientation",
                            "expected \"random\", a quaternion [w, x, y, z] or { axis, degrees }, "
                            "got \"" + *text + "\"");
            }
            spawn.randomOrientation = true;
            return;
        }
        body.orientation = reader.orientation(node, key + ".orientation");
    });
    ifPresent(table, "angular_speed", [&](const toml::node& node) {
        std::tie(spawn.angularSpeedLow, spawn.angularSpeedHigh) =
            readInterval(reader, node, key + ".angular_speed");
        if (spawn.angularSpeedLow < 0.0) {
            reader.fail(node, key + ".angular_speed",
                        "must be >= 0, got low = " + formatReal(spawn.angularSpeedLow));
        }
        checkAngularSpeed(reader, node, key + ".angular_speed",
                          Vec3(spawn.angularSpeedHigh, 0.0, 0.0), scenario.dt, context);
    });
    ifPresent(table, "velocity", [&](const toml::node& node) {
        body.linearVelocity = reader.vec3(node, key + ".velocity");
        reader.checkRange(node, key + ".velocity", vectorLength(body.linearVelocity), kSpeedRange,
                          "the speed ", context);
    });
    readMaterial(reader, table, key, context, body.material);
    // The farthest grid corner must lie within the valid positions.
    const auto side = static_cast<Real>(
        std::ceil(std::sqrt(static_cast<Real>(spawn.count))));
    const Real corner = 0.5 * (side - 1.0) * spawn.spacing * std::sqrt(2.0) +
                        std::abs(scenario.ground ? scenario.ground->height : 0.0) +
                        spawn.heightHigh;
    reader.checkRange(table, key + ".spacing", corner, kPositionRange,
                      "the farthest body's distance from the origin ", context);
    return spawn;
}

} // namespace

void readSpawns(const TomlReader& reader, const toml::table& root, Scenario& scenario)
{
    const toml::array* spawns = arrayOfTables(reader, root, "spawn");
    if (spawns == nullptr) {
        return;
    }
    const Real groundHeight = scenario.ground ? scenario.ground->height : 0.0;
    for (std::size_t i = 0; i < spawns->size(); ++i) {
        const toml::table& table = *spawns->get(i)->as_table();
        SpawnSpec spawn = readSpawn(reader, table, i, scenario);
        std::vector<BodySpec> bodies =
            spawnBodies(spawn, groundHeight, "spawn" + std::to_string(i + 1) + "_");
        checkSpawnClearance(reader, table, "spawn[" + std::to_string(i) + "]", scenario, bodies);
        scenario.bodies.insert(scenario.bodies.end(), std::make_move_iterator(bodies.begin()),
                               std::make_move_iterator(bodies.end()));
        scenario.spawns.push_back(spawn);
    }
}

} // namespace tumble::scenario::detail

namespace tumble::scenario {

std::vector<BodySpec> spawnBodies(const SpawnSpec& spawn, Real groundHeight,
                                  std::string_view prefix)
{
    const auto side = static_cast<std::size_t>(
        std::ceil(std::sqrt(static_cast<Real>(spawn.count))));
    const Real centre = 0.5 * static_cast<Real>(side - 1);
    RandomDraws draws(spawn.seed);
    std::vector<BodySpec> bodies;
    bodies.reserve(spawn.count);
    for (std::size_t k = 0; k < spawn.count; ++k) {
        BodySpec body;
        body.name = std::string(prefix) + std::to_string(k + 1);
        body.where = spawn.where;
        body.def = spawn.body;
        const Real column = static_cast<Real>(k % side) - centre;
        const Real row = static_cast<Real>(k / side) - centre;
        const Real height = draws.uniform(spawn.heightLow, spawn.heightHigh);
        body.def.position =
            Vec3(column * spawn.spacing, groundHeight + height, row * spawn.spacing);
        if (spawn.randomOrientation) {
            body.def.orientation = draws.rotation();
        }
        const Real angularSpeed = draws.uniform(spawn.angularSpeedLow, spawn.angularSpeedHigh);
        body.def.angularVelocity = angularSpeed * draws.direction();
        bodies.push_back(std::move(body));
    }
    return bodies;
}

} // namespace tumble::scenario
