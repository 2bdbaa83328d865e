// The [throw] table of a dice scenario, checked against the die and the world and turned into a
// ThrowSpec.
#include "read_throw.hpp"

#include "messages.hpp"
#include "schema.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace tumble::scenario::detail {

namespace {

/// A number x (the range [x, x]) or an array [min, max] with min <= max.
DrawRange readDrawRange(const TomlReader& reader, const toml::node& node, const std::string& key)
{
    if (node.is_number()) {
        const Real value = reader.real(node, key);
        return DrawRange{value, value};
    }
    const toml::array* array = node.as_array();
    if (array == nullptr || array->size() != 2) {
        reader.fail(node, key, "expected a range [min, max] or a single number, got " +
                                   describeNode(node));
    }
    const DrawRange range{reader.real(*array->get(0), key + "[0]"),
                          reader.real(*array->get(1), key + "[1]")};
    if (range.min > range.max) {
        reader.fail(node, key,
                    "min must be <= max, got [" + formatReal(range.min) + ", " +
                        formatReal(range.max) + "]");
    }
    return range;
}

/// Fails unless the whole range is >= 0.
void checkNonNegative(const TomlReader& reader, const toml::node& node, const std::string& key,
                      const DrawRange& range)
{
    if (range.min < 0.0) {
        reader.fail(node, key, "must be >= 0, got a minimum of " + formatReal(range.min));
    }
}

void readRanges(const TomlReader& reader, const toml::table& table, const Scenario& scenario,
                ThrowSpec& spec)
{
    const Real halfDiagonal = largestHalfDiagonal(scenario);
    ifPresent(table, "height", [&](const toml::node& node) {
        spec.height = readDrawRange(reader, node, "throw.height");
        checkNonNegative(reader, node, "throw.height", spec.height);
        // a die released lower than its half diagonal could start with a corner in the ground
        if (spec.height.min < halfDiagonal) {
            reader.fail(node, "throw.height",
                        "must be at least " + formatReal(halfDiagonal) +
                            " m (half the die's diagonal, so no corner starts below the ground), "
                            "got a minimum of " +
                            formatReal(spec.height.min));
        }
        reader.checkRange(node, "throw.height", spec.height.max, kPositionRange, "the maximum ");
    });
    ifPresent(table, "speed", [&](const toml::node& node) {
        spec.speed = readDrawRange(reader, node, "throw.speed");
        checkNonNegative(reader, node, "throw.speed", spec.speed);
        reader.checkRange(node, "throw.speed", spec.speed.max, kSpeedRange, "the maximum ");
    });
    ifPresent(table, "heading", [&](const toml::node& node) {
        const DrawRange degrees = readDrawRange(reader, node, "throw.heading");
        if (degrees.min < -360.0 || degrees.max > 360.0) {
            reader.fail(node, "throw.heading",
                        "must lie within [-360, 360] degrees, got [" + formatReal(degrees.min) +
                            ", " + formatReal(degrees.max) + "]");
        }
        spec.heading = {degrees.min * std::numbers::pi / 180.0,
                        degrees.max * std::numbers::pi / 180.0};
    });
    ifPresent(table, "vertical_speed", [&](const toml::node& node) {
        spec.verticalSpeed = readDrawRange(reader, node, "throw.vertical_speed");
        const Real largest = std::max(std::abs(spec.verticalSpeed.min),
                                      std::abs(spec.verticalSpeed.max));
        reader.checkRange(node, "throw.vertical_speed", largest, kSpeedRange,
                          "the largest magnitude ");
    });
    ifPresent(table, "angular_speed", [&](const toml::node& node) {
        spec.angularSpeed = readDrawRange(reader, node, "throw.angular_speed");
        checkNonNegative(reader, node, "throw.angular_speed", spec.angularSpeed);
        reader.checkRange(node, "throw.angular_speed", spec.angularSpeed.max, kAngularSpeedRange,
                          "the maximum ");
        reader.checkRange(node, "throw.angular_speed", spec.angularSpeed.max * scenario.dt,
                          kTurnPerStepRange,
                          "the largest angle turned in one step (max angular_speed * dt, dt = " +
                              formatReal(scenario.dt) + " s) ");
    });
}

/// Checks the keys that pick the release points against the dice and the ground.
void checkReleaseModel(const TomlReader& reader, const toml::table& table,
                       const Scenario& scenario, const ThrowSpec& spec)
{
    if (spec.region && table.contains("height")) {
        reader.fail(*table.get("height"), "throw.height",
                    "give either height or region: the region holds the release heights");
    }
    if (!spec.region && !scenario.ground) {
        reader.fail(table, "throw",
                    "a [throw] scenario without a region needs a [ground] for the dice to land on");
    }
    if (!spec.region && spec.release == ThrowRelease::Each && throwDiceCount(scenario) > 1) {
        reader.fail(table, "throw",
                    "several dice need a region (or release = \"cluster\"): released each on "
                    "its own above the origin they would start inside each other");
    }
}

} // namespace

void readThrow(const TomlReader& reader, const toml::table& root, Scenario& scenario)
{
    const toml::node* node = root.get("throw");
    if (node == nullptr) {
        return;
    }
    const toml::table& table = reader.table(*node, "throw", "a table ([throw])");
    reader.checkKeys(table, "throw", kThrowKeys);
    // the dice are the dynamic bodies; their positions and velocities are drawn
    if (throwDiceCount(scenario) == 0) {
        reader.fail(table, "throw",
                    "a [throw] scenario needs at least one dynamic [[body]] (a die), got none");
    }
    if (!scenario.impulses.empty()) {
        reader.fail(table, "throw", "a [throw] scenario takes no [[impulse]]");
    }
    ThrowSpec spec;
    readRelease(reader, table, spec);
    checkReleaseModel(reader, table, scenario, spec);
    readRanges(reader, table, scenario, spec);
    ifPresent(table, "orientation", [&](const toml::node& orientation) {
        spec.orientation = reader.choice(orientation, "throw.orientation",
                                         kThrowOrientationNames) == 0
                               ? ThrowOrientation::Random
                               : ThrowOrientation::Body;
    });
    ifPresent(table, "max_time", [&](const toml::node& maxTime) {
        spec.maxTime = reader.positive(maxTime, "throw.max_time");
        reader.checkRange(maxTime, "throw.max_time", spec.maxTime / scenario.dt, kStepCountRange,
                          "the number of steps max_time / dt ");
    });
    // the defaults are checked too: a tiny die or a coarse dt can make them invalid
    if (!spec.region && !table.contains("height") &&
        spec.height.min < largestHalfDiagonal(scenario)) {
        reader.fail(table, "throw.height",
                    "the default [0.5, 1.0] m is lower than half the die's diagonal; give a "
                    "height");
    }
    if (!table.contains("angular_speed") &&
        spec.angularSpeed.max * scenario.dt > kTurnPerStepRange.high) {
        reader.fail(table, "throw.angular_speed",
                    "the default maximum of 20 rad/s turns more than 0.5 rad per step at dt = " +
                        formatReal(scenario.dt) + " s; give a smaller angular_speed or dt");
    }
    scenario.throwSpec = spec;
}

} // namespace tumble::scenario::detail
