// buildWorld: a World holding a scenario's settings, ground and bodies.
#include "tumble/scenario/scenario.hpp"

#include <cmath>

namespace tumble::scenario {

namespace {

/// A Scenario may be filled in by hand rather than read from a file, so the body definitions are
/// checked here too: the World only asserts, and a bad definition should be reported, not abort.
void checkBody(const BodySpec& spec)
{
    const BodyDef& def = spec.def;
    const auto fail = [&](const char* key, const char* problem) {
        throw ScenarioError(spec.where, spec.name + "." + key, problem);
    };
    if (def.motion == BodyMotion::Static &&
        (lengthSquared(def.linearVelocity) > 0.0 || lengthSquared(def.angularVelocity) > 0.0)) {
        fail("velocity", "a static body does not move");
    }
    if (!(def.mass > 0.0) || !std::isfinite(def.mass)) {
        fail("mass", "must be positive and finite");
    }
    const Vec3& size = def.shape.size;
    if (!(size.x > 0.0 && size.y > 0.0 && size.z > 0.0) || !isFinite(size)) {
        fail("size", "every component must be positive and finite");
    }
    if (!isFinite(def.position) || !isFinite(def.linearVelocity) ||
        !isFinite(def.angularVelocity)) {
        fail("position", "position and velocities must be finite");
    }
    if (!isFinite(def.orientation) || std::abs(glm::length(def.orientation) - 1.0) > 1e-6) {
        fail("orientation", "must be a finite unit quaternion");
    }
}

} // namespace

BuiltWorld buildWorld(const Scenario& scenario)
{
    BuiltWorld built{World(scenario.settings), {}};
    built.world.setGround(scenario.ground);
    built.world.setGroundMaterial(scenario.groundMaterial);
    for (const StaticPlane& plane : scenario.planes) {
        if (!isFinite(plane.point) || !isFinite(plane.normal) ||
            std::abs(glm::length(plane.normal) - 1.0) > 1e-9) {
            throw ScenarioError(SourceLocation{scenario.sourceName, 0}, "plane",
                                "needs a finite point and a unit normal");
        }
        built.world.addPlane(plane);
    }
    built.bodies.reserve(scenario.bodies.size());
    for (const BodySpec& spec : scenario.bodies) {
        checkBody(spec);
        built.bodies.push_back(built.world.createBody(spec.def));
    }
    return built;
}

} // namespace tumble::scenario
