// A [[spawn]]'s bodies must start clear of static planes, of [[body]] entries and of the bodies of
// earlier spawns, as a [[body]] must (docs/scenario-format.md). Bodies of one spawn cannot
// overlap: its spacing is at least the body's diagonal.
#include "read_entries.hpp"

#include "messages.hpp"

#include <algorithm>
#include <cmath>

namespace tumble::scenario::detail {

namespace {

/// A body's extent along x, bounded by the sphere through its corners.
struct XInterval {
    Real low = 0.0;
    Real high = 0.0;
    std::size_t body = 0;
};

Real cornerRadius(const BodySpec& spec) { return glm::length(spec.def.shape.halfExtents()); }

Transform poseOf(const BodySpec& spec)
{
    return {spec.def.position, glm::normalize(spec.def.orientation)};
}

[[noreturn]] void failOverlap(const TomlReader& reader, const toml::table& table,
                              const std::string& key, const BodySpec& spawned,
                              const std::string& what, Real depth, Real tolerance)
{
    reader.fail(table, key,
                "body \"" + spawned.name + "\" starts " + formatReal(depth) + " m inside " + what +
                    " (more than the contact tolerance " + formatReal(tolerance) +
                    " m): move the spawn's height or the other body apart");
}

} // namespace

void checkSpawnClearance(const TomlReader& reader, const toml::table& table,
                         const std::string& key, const Scenario& scenario,
                         std::span<const BodySpec> spawned)
{
    const Real tolerance = scenario.settings.contactTolerance;
    for (const BodySpec& body : spawned) {
        for (std::size_t k = 0; k < scenario.planes.size(); ++k) {
            const Real depth = cuboidHalfSpaceDepth(poseOf(body), body.def.shape.halfExtents(),
                                                    scenario.planes[k]);
            if (depth > tolerance) {
                failOverlap(reader, table, key, body, "plane[" + std::to_string(k) + "]", depth,
                            tolerance);
            }
        }
    }
    // sort and sweep along x over the bodies already read and the new ones (decision 0006): only
    // pairs of an old and a new body whose corner spheres meet are measured
    const std::size_t old = scenario.bodies.size();
    std::vector<XInterval> intervals;
    intervals.reserve(old + spawned.size());
    const auto specOf = [&](std::size_t i) -> const BodySpec& {
        return i < old ? scenario.bodies[i] : spawned[i - old];
    };
    for (std::size_t i = 0; i < old + spawned.size(); ++i) {
        const BodySpec& spec = specOf(i);
        const Real radius = cornerRadius(spec);
        intervals.push_back({spec.def.position.x - radius, spec.def.position.x + radius, i});
    }
    std::sort(intervals.begin(), intervals.end(),
              [](const XInterval& a, const XInterval& b) { return a.low < b.low; });
    for (std::size_t i = 0; i < intervals.size(); ++i) {
        for (std::size_t j = i + 1; j < intervals.size() && intervals[j].low <= intervals[i].high;
             ++j) {
            const std::size_t a = std::min(intervals[i].body, intervals[j].body);
            const std::size_t b = std::max(intervals[i].body, intervals[j].body);
            if (a >= old || b < old) {
                continue;
            }
            const BodySpec& other = specOf(a);
            const BodySpec& body = specOf(b);
            if (glm::length(other.def.position - body.def.position) >
                cornerRadius(other) + cornerRadius(body)) {
                continue;
            }
            const Real depth =
                cuboidOverlapDepth(poseOf(body), body.def.shape.halfExtents(), poseOf(other),
                                   other.def.shape.halfExtents());
            if (depth > tolerance) {
                failOverlap(reader, table, key, body, "body \"" + other.name + "\"", depth,
                            tolerance);
            }
        }
    }
}

} // namespace tumble::scenario::detail
