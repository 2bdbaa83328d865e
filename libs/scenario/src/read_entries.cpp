// The [[body]] and [[impulse]] arrays of a scenario file, checked and turned into specs.
#include "read_entries.hpp"

#include "messages.hpp"
#include "schema.hpp"
#include "vector_length.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <optional>
#include <string>

namespace tumble::scenario::detail {

/// An angular velocity within the valid range, and turning the body by at most the valid angle
/// in one step of length dt.
void checkAngularSpeed(const TomlReader& reader, const toml::node& node, const std::string& key,
                       const Vec3& angularVelocity, Real dt, const std::string& context)
{
    const Real speed = vectorLength(angularVelocity);
    reader.checkRange(node, key, speed, kAngularSpeedRange, "the angular speed ", context);
    reader.checkRange(node, key, speed * dt, kTurnPerStepRange,
                      "the angle turned in one step (|angular_velocity| dt, dt = " +
                          formatReal(dt) + " s) ",
                      context);
}

/// size or scale (not both) into the cuboid's full extents.
void readShape(const TomlReader& reader, const toml::table& table, const std::string& key,
               const std::string& context, BodyDef& def)
{
    const toml::node* size = table.get("size");
    const toml::node* scale = table.get("scale");
    if (size != nullptr && scale != nullptr) {
        reader.fail(*scale, key + ".scale",
                    "give size or scale, not both (size is the full extents; scale multiplies "
                    "the default 2 x 2 x 2 cube)" +
                        context);
    }
    if (size != nullptr) {
        def.shape.size = reader.positiveVec3(*size, key + ".size", context);
    }
    if (scale != nullptr) {
        def.shape.size = Cuboid{}.size * reader.positiveVec3(*scale, key + ".scale", context);
    }
    const toml::node* given = size != nullptr ? size : scale;
    if (given != nullptr) {
        const std::string givenKey = key + (size != nullptr ? ".size" : ".scale");
        const Vec3& extents = def.shape.size;
        const Real shortest = std::min({extents.x, extents.y, extents.z});
        const Real longest = std::max({extents.x, extents.y, extents.z});
        reader.checkRange(*given, givenKey, shortest, kSizeRange, "every edge ", context);
        reader.checkRange(*given, givenKey, longest, kSizeRange, "every edge ", context);
        reader.checkRange(*given, givenKey, longest / shortest, kAspectRange,
                          "the longest edge over the shortest ", context);
    }
}

/// elasticity, friction and static_friction into the body's Material.
void readMaterial(const TomlReader& reader, const toml::table& table, const std::string& key,
                  const std::string& context, Material& material)
{
    ifPresent(table, "elasticity", [&](const toml::node& node) {
        const Real elasticity = reader.real(node, key + ".elasticity");
        if (elasticity < 0.0 || elasticity > 1.0) {
            reader.fail(node, key + ".elasticity",
                        "must be in [0, 1], got " + formatReal(elasticity) + context);
        }
        material.restitution = elasticity;
    });
    ifPresent(table, "friction", [&](const toml::node& node) {
        material.friction = reader.nonNegative(node, key + ".friction", context);
        reader.checkRange(node, key + ".friction", material.friction, kFrictionRange, {}, context);
    });
    ifPresent(table, "static_friction", [&](const toml::node& node) {
        const Real staticFriction = reader.real(node, key + ".static_friction");
        if (staticFriction < material.friction) {
            reader.fail(node, key + ".static_friction",
                        "must be >= friction (" + formatReal(material.friction) + "), got " +
                            formatReal(staticFriction) + context);
        }
        reader.checkRange(node, key + ".static_friction", staticFriction, kFrictionRange, {},
                          context);
        material.staticFriction = staticFriction;
    });
}

namespace {

BodySpec readBody(const TomlReader& reader, const toml::table& table, std::size_t index, Real dt)
{
    const std::string key = "body[" + std::to_string(index) + "]";
    reader.checkKeys(table, key, kBodyKeys);
    BodySpec spec;
    spec.where = reader.locate(table);
    spec.name = "body" + std::to_string(index + 1);
    ifPresent(table, "name", [&](const toml::node& node) {
        spec.name = reader.string(node, key + ".name");
        if (spec.name.empty()) {
            reader.fail(node, key + ".name", "must not be empty");
        }
    });
    // Added to range problems so that the message names the body, not only its index.
    const std::string context = " (body \"" + spec.name + "\")";
    BodyDef& def = spec.def;
    ifPresent(table, "motion", [&](const toml::node& node) {
        def.motion = static_cast<BodyMotion>(reader.choice(node, key + ".motion", kMotionNames));
    });
    if (def.motion == BodyMotion::Static) {
        // a static body is fixed geometry: what would move it is a mistake, not a default
        for (const std::string_view dynamicKey : kDynamicOnlyBodyKeys) {
            ifPresent(table, dynamicKey, [&](const toml::node& node) {
                reader.fail(node, key + "." + std::string(dynamicKey),
                            "a static body takes no " + std::string(dynamicKey) +
                                " (it does not move)" + context);
            });
        }
        def.materialGiven = std::any_of(kMaterialKeys.begin(), kMaterialKeys.end(),
                                        [&](std::string_view k) { return table.contains(k); });
    }
    readShape(reader, table, key, context, def);
    ifPresent(table, "mass", [&](const toml::node& node) {
        def.mass = reader.positive(node, key + ".mass", context);
        reader.checkRange(node, key + ".mass", def.mass, kMassRange, {}, context);
    });
    ifPresent(table, "position", [&](const toml::node& node) {
        def.position = reader.vec3(node, key + ".position");
        reader.checkRange(node, key + ".position", vectorLength(def.position), kPositionRange,
                          "the distance from the origin ", context);
    });
    ifPresent(table, "orientation", [&](const toml::node& node) {
        def.orientation = reader.orientation(node, key + ".orientation");
    });
    ifPresent(table, "velocity", [&](const toml::node& node) {
        def.linearVelocity = reader.vec3(node, key + ".velocity");
        reader.checkRange(node, key + ".velocity", vectorLength(def.linearVelocity), kSpeedRange,
                          "the speed ", context);
    });
    ifPresent(table, "angular_velocity", [&](const toml::node& node) {
        def.angularVelocity = reader.vec3(node, key + ".angular_velocity");
        checkAngularSpeed(reader, node, key + ".angular_velocity", def.angularVelocity, dt,
                          context);
    });
    readMaterial(reader, table, key, context, def.material);
    return spec;
}

/// A body must start on or above the ground: one inside it would be pushed out by the first
/// contact, gaining energy from nowhere (issue 14, item 9). [[spawn]] and [throw] check their
/// draws the same way.
void checkAboveGround(const TomlReader& reader, const toml::table& table, const BodySpec& spec,
                      const std::optional<Plane>& ground, const std::string& key)
{
    if (!ground) {
        return;
    }
    const BodyDef& def = spec.def;
    // the half height of the rotated cuboid: each body axis's vertical part times its half extent
    const Mat3 rotation = glm::mat3_cast(def.orientation);
    const Vec3 half = def.shape.halfExtents();
    const Real halfHeight = std::abs(rotation[0].y) * half.x + std::abs(rotation[1].y) * half.y +
                            std::abs(rotation[2].y) * half.z;
    const Real lowest = def.position.y - halfHeight;
    // rounding of a body placed exactly on the ground is not a problem
    const Real tolerance =
        1e-9 * (1.0 + std::abs(def.position.y) + std::abs(ground->height) + glm::length(half));
    if (lowest >= ground->height - tolerance) {
        return;
    }
    const toml::node* position = table.get("position");
    reader.fail(position != nullptr ? *position : static_cast<const toml::node&>(table),
                key + ".position",
                "the lowest vertex is at y = " + formatReal(lowest) + " m, " +
                    formatReal(ground->height - lowest) + " m below the ground (y = " +
                    formatReal(ground->height) +
                    " m): a body must start on or above the ground (body \"" + spec.name +
                    "\")");
}

/// The impulse (and offset) or the target (velocity and angular_velocity) of an entry.
void readImpulseValue(const TomlReader& reader, const toml::table& table, Real dt,
                      ImpulseSpec& spec)
{
    const std::string& key = spec.label;
    const toml::node* impulse = table.get("impulse");
    const toml::node* offset = table.get("offset");
    const toml::node* velocity = table.get("velocity");
    const toml::node* angularVelocity = table.get("angular_velocity");
    const bool isTarget = velocity != nullptr || angularVelocity != nullptr;
    if (impulse != nullptr && isTarget) {
        reader.fail(table, key,
                    "give either impulse (with an optional offset) or a target velocity and "
                    "angular_velocity, not both");
    }
    if (impulse == nullptr && !isTarget) {
        reader.fail(table, key,
                    "needs either impulse (with an optional offset) or a target velocity and "
                    "angular_velocity");
    }
    if (impulse != nullptr) {
        spec.impulse = reader.vec3(*impulse, key + ".impulse");
        reader.checkRange(*impulse, key + ".impulse", vectorLength(*spec.impulse), kImpulseRange,
                          "the length ");
        spec.offset = offset == nullptr ? Vec3(0.0) : reader.vec3(*offset, key + ".offset");
        if (offset != nullptr) {
            reader.checkRange(*offset, key + ".offset", vectorLength(*spec.offset), kOffsetRange,
                              "the length ");
        }
        return;
    }
    if (offset != nullptr) {
        reader.fail(*offset, key + ".offset",
                    "offset goes with impulse; a target (velocity, angular_velocity) is solved "
                    "for its own point");
    }
    if (velocity == nullptr || angularVelocity == nullptr) {
        reader.fail(table, key + (velocity == nullptr ? ".velocity" : ".angular_velocity"),
                    "missing: a target needs both velocity and angular_velocity (give the "
                    "current value to keep one unchanged)");
    }
    spec.targetVelocity = reader.vec3(*velocity, key + ".velocity");
    reader.checkRange(*velocity, key + ".velocity", vectorLength(*spec.targetVelocity),
                      kSpeedRange, "the speed ");
    spec.targetAngularVelocity = reader.vec3(*angularVelocity, key + ".angular_velocity");
    checkAngularSpeed(reader, *angularVelocity, key + ".angular_velocity",
                      *spec.targetAngularVelocity, dt, {});
}

ImpulseSpec readImpulse(const TomlReader& reader, const toml::table& table, std::size_t index,
                        Real dt)
{
    ImpulseSpec spec;
    spec.label = "impulse[" + std::to_string(index) + "]";
    const std::string& key = spec.label;
    reader.checkKeys(table, key, kImpulseKeys);
    spec.where = reader.locate(table);
    const toml::node* at = table.get("at");
    if (at == nullptr) {
        reader.fail(table, key + ".at", "missing: the time in s at which the impulse acts");
    }
    spec.at = reader.nonNegative(*at, key + ".at");
    const toml::node* body = table.get("body");
    if (body == nullptr) {
        reader.fail(table, key + ".body", "missing: the name of the body the impulse acts on");
    }
    spec.body = reader.string(*body, key + ".body");
    readImpulseValue(reader, table, dt, spec);
    return spec;
}

std::string bodyNames(const Scenario& scenario)
{
    std::string names;
    for (const BodySpec& body : scenario.bodies) {
        names += names.empty() ? "" : ", ";
        names += body.name;
    }
    return names;
}

} // namespace

/// The array of tables `name` ([[body]], [[impulse]]), or null when absent.
const toml::array* arrayOfTables(const TomlReader& reader, const toml::table& root,
                                 std::string_view name)
{
    const toml::node* node = root.get(name);
    if (node == nullptr) {
        return nullptr;
    }
    const toml::array* array = node->as_array();
    if (array == nullptr || !array->is_array_of_tables()) {
        reader.fail(*node, std::string(name),
                    "expected an array of tables ([[" + std::string(name) + "]]), got " +
                        describeNode(*node));
    }
    return array;
}

void readBodies(const TomlReader& reader, const toml::table& root, Scenario& scenario)
{
    const toml::array* bodies = arrayOfTables(reader, root, "body");
    if (bodies == nullptr) {
        return;
    }
    std::map<std::string, std::size_t> indexByName;
    for (std::size_t i = 0; i < bodies->size(); ++i) {
        const toml::table& table = *bodies->get(i)->as_table();
        BodySpec spec = readBody(reader, table, i, scenario.dt);
        // a [throw] die's position is drawn per throw, and read_throw checks the draws; static
        // bodies may overlap the ground and each other
        if (root.get("throw") == nullptr && spec.def.motion == BodyMotion::Dynamic) {
            const std::string key = "body[" + std::to_string(i) + "]";
            checkAboveGround(reader, table, spec, scenario.ground, key);
            checkClearOfStaticPlanes(reader, table, spec, scenario, key);
        }
        const auto [found, inserted] = indexByName.emplace(spec.name, i);
        if (!inserted) {
            const toml::node* name = table.get("name");
            reader.fail(name != nullptr ? *name : static_cast<const toml::node&>(table),
                        "body[" + std::to_string(i) + "].name",
                        "duplicate body name \"" + spec.name + "\" (also body[" +
                            std::to_string(found->second) + "])");
        }
        if (root.get("throw") == nullptr) {
            checkClearOfBodies(reader, table, spec, scenario, "body[" + std::to_string(i) + "]");
        }
        scenario.bodies.push_back(std::move(spec));
    }
}

void readImpulses(const TomlReader& reader, const toml::table& root, Scenario& scenario)
{
    const toml::array* impulses = arrayOfTables(reader, root, "impulse");
    if (impulses == nullptr) {
        return;
    }
    for (std::size_t i = 0; i < impulses->size(); ++i) {
        const toml::table& table = *impulses->get(i)->as_table();
        ImpulseSpec spec = readImpulse(reader, table, i, scenario.dt);
        const bool known =
            std::any_of(scenario.bodies.begin(), scenario.bodies.end(),
                        [&](const BodySpec& body) { return body.name == spec.body; });
        if (!known) {
            reader.fail(*table.get("body"), spec.label + ".body",
                        "no body named \"" + spec.body + "\" (bodies: " + bodyNames(scenario) +
                            ")");
        }
        scenario.impulses.push_back(std::move(spec));
    }
    std::stable_sort(scenario.impulses.begin(), scenario.impulses.end(),
                     [](const ImpulseSpec& a, const ImpulseSpec& b) { return a.at < b.at; });
}

} // namespace tumble::scenario::detail
