// The [throw] keys that say where the dice start: release, cluster_radius and region.
#include "read_throw.hpp"

#include "messages.hpp"
#include "schema.hpp"
#include "valid_ranges.hpp"
#include "vector_length.hpp"

#include <algorithm>
#include <string>

namespace tumble::scenario::detail {

namespace {

/// region = { min = [x, y, z], max = [x, y, z] } with min <= max in every component.
ThrowRegion readRegion(const TomlReader& reader, const toml::node& node)
{
    const toml::table& table = reader.table(node, "throw.region",
                                            "a table { min = [x, y, z], max = [x, y, z] }");
    reader.checkKeys(table, "throw.region", kThrowRegionKeys);
    const toml::node* low = table.get("min");
    const toml::node* high = table.get("max");
    if (low == nullptr || high == nullptr) {
        reader.fail(table, low == nullptr ? "throw.region.min" : "throw.region.max",
                    "missing: a region gives both corners, min and max, m");
    }
    ThrowRegion region{reader.vec3(*low, "throw.region.min"), reader.vec3(*high, "throw.region.max")};
    reader.checkRange(*low, "throw.region.min", vectorLength(region.min), kPositionRange);
    reader.checkRange(*high, "throw.region.max", vectorLength(region.max), kPositionRange);
    for (int axis = 0; axis < 3; ++axis) {
        if (region.min[axis] > region.max[axis]) {
            reader.fail(*high, "throw.region",
                        std::string("min must be <= max in every component, got ") +
                            "xyz"[axis] + " from " + formatReal(region.min[axis]) + " to " +
                            formatReal(region.max[axis]));
        }
    }
    return region;
}

} // namespace

std::size_t throwDiceCount(const Scenario& scenario)
{
    return static_cast<std::size_t>(
        std::count_if(scenario.bodies.begin(), scenario.bodies.end(), [](const BodySpec& body) {
            return body.def.motion == BodyMotion::Dynamic;
        }));
}

Real largestHalfDiagonal(const Scenario& scenario)
{
    Real largest = 0.0;
    for (const BodySpec& body : scenario.bodies) {
        if (body.def.motion == BodyMotion::Dynamic) {
            largest = std::max(largest, 0.5 * glm::length(body.def.shape.size));
        }
    }
    return largest;
}

void readRelease(const TomlReader& reader, const toml::table& table, ThrowSpec& spec)
{
    ifPresent(table, "release", [&](const toml::node& node) {
        spec.release = reader.choice(node, "throw.release", kThrowReleaseNames) == 0
                           ? ThrowRelease::Each
                           : ThrowRelease::Cluster;
    });
    ifPresent(table, "cluster_radius", [&](const toml::node& node) {
        if (spec.release != ThrowRelease::Cluster) {
            reader.fail(node, "throw.cluster_radius",
                        "applies only with release = \"cluster\"");
        }
        spec.clusterRadius = reader.positive(node, "throw.cluster_radius");
        reader.checkRange(node, "throw.cluster_radius", spec.clusterRadius, kPositionRange);
    });
    ifPresent(table, "region",
              [&](const toml::node& node) { spec.region = readRegion(reader, node); });
}

} // namespace tumble::scenario::detail
