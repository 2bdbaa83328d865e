// Static geometry of a scenario file: [[plane]] entries, the ground's material, and the checks
// that no dynamic body starts inside static geometry or another body.
#include "read_entries.hpp"

#include "messages.hpp"
#include "schema.hpp"
#include "vector_length.hpp"

#include <algorithm>
#include <cmath>

namespace tumble::scenario::detail {

namespace {

/// Where to point a message about a body's placement: its position, else its table.
const toml::node& placementNode(const toml::table& table)
{
    const toml::node* position = table.get("position");
    return position != nullptr ? *position : static_cast<const toml::node&>(table);
}

} // namespace

std::optional<Material> readOptionalMaterial(const TomlReader& reader, const toml::table& table,
                                             const std::string& key)
{
    const bool given = std::any_of(kMaterialKeys.begin(), kMaterialKeys.end(),
                                   [&](std::string_view k) { return table.contains(k); });
    if (!given) {
        return std::nullopt;
    }
    Material material;
    readMaterial(reader, table, key, {}, material);
    return material;
}

void readPlanes(const TomlReader& reader, const toml::table& root, Scenario& scenario)
{
    const toml::array* planes = arrayOfTables(reader, root, "plane");
    if (planes == nullptr) {
        return;
    }
    for (std::size_t i = 0; i < planes->size(); ++i) {
        const toml::table& table = *planes->get(i)->as_table();
        const std::string key = "plane[" + std::to_string(i) + "]";
        reader.checkKeys(table, key, kPlaneKeys);
        const toml::node* point = table.get("point");
        const toml::node* normal = table.get("normal");
        if (point == nullptr || normal == nullptr) {
            reader.fail(table, key + (point == nullptr ? ".point" : ".normal"),
                        point == nullptr ? "missing: a point on the plane, m"
                                         : "missing: the plane's outward normal");
        }
        StaticPlane plane;
        plane.point = reader.vec3(*point, key + ".point");
        reader.checkRange(*point, key + ".point", vectorLength(plane.point), kPositionRange,
                          "the distance from the origin ");
        const Vec3 direction = reader.vec3(*normal, key + ".normal");
        const Real length = vectorLength(direction);
        if (!(length > 0.0) || !std::isfinite(length)) {
            reader.fail(*normal, key + ".normal", "must be a nonzero vector, got [" +
                                                      formatReal(direction.x) + ", " +
                                                      formatReal(direction.y) + ", " +
                                                      formatReal(direction.z) + "]");
        }
        plane.normal = direction / length;
        plane.material = readOptionalMaterial(reader, table, key);
        scenario.planes.push_back(plane);
    }
}

void checkClearOfStaticPlanes(const TomlReader& reader, const toml::table& table,
                              const BodySpec& spec, const Scenario& scenario,
                              const std::string& key)
{
    const Transform pose{spec.def.position, glm::normalize(spec.def.orientation)};
    const Real tolerance = scenario.settings.contactTolerance;
    for (std::size_t k = 0; k < scenario.planes.size(); ++k) {
        const Real depth =
            cuboidHalfSpaceDepth(pose, spec.def.shape.halfExtents(), scenario.planes[k]);
        if (depth > tolerance) {
            reader.fail(placementNode(table), key + ".position",
                        "starts " + formatReal(depth) + " m inside plane[" + std::to_string(k) +
                            "] (more than the contact tolerance " + formatReal(tolerance) +
                            " m): a dynamic body must start outside static geometry (body \"" +
                            spec.name + "\")");
        }
    }
}

void checkClearOfBodies(const TomlReader& reader, const toml::table& table, const BodySpec& spec,
                        const Scenario& scenario, const std::string& key)
{
    const Transform pose{spec.def.position, glm::normalize(spec.def.orientation)};
    const Real tolerance = scenario.settings.contactTolerance;
    for (const BodySpec& other : scenario.bodies) {
        if (spec.def.motion == BodyMotion::Static && other.def.motion == BodyMotion::Static) {
            continue;
        }
        const Real depth = cuboidOverlapDepth(
            pose, spec.def.shape.halfExtents(),
            {other.def.position, glm::normalize(other.def.orientation)},
            other.def.shape.halfExtents());
        if (depth > tolerance) {
            reader.fail(placementNode(table), key + ".position",
                        "overlaps body \"" + other.name + "\" by " + formatReal(depth) +
                            " m (more than the contact tolerance " + formatReal(tolerance) +
                            " m): bodies must start apart or touching (body \"" + spec.name +
                            "\")");
        }
    }
}

} // namespace tumble::scenario::detail
