// The JavaScript face of the module (Embind): Module.Simulation and Module.impulseExperiments.
// Vectors cross as plain arrays [x, y, z]; every number is the engine's double, unrounded.
#include "web_simulation.hpp"

#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <optional>

namespace tumble::web {
namespace {

using emscripten::val;

val toArray(const Vec3& v)
{
    val array = val::array();
    array.call<void>("push", v.x, v.y, v.z);
    return array;
}

Vec3 toVec3(const val& array)
{
    return {array[0].as<double>(), array[1].as<double>(), array[2].as<double>()};
}

std::optional<Vec3> toOptionalVec3(const val& value)
{
    if (value.isNull() || value.isUndefined()) {
        return std::nullopt;
    }
    return toVec3(value);
}

val optionalArray(const std::optional<Vec3>& v) { return v ? toArray(*v) : val::null(); }

val state(const WebSimulation& simulation, std::size_t index)
{
    val array = val::array();
    for (const Real value : simulation.state(index)) {
        array.call<void>("push", value);
    }
    return array;
}

val size(const WebSimulation& simulation, std::size_t index)
{
    return toArray(simulation.size(index));
}

/// The points of a manifold and their average.
val manifoldObject(const ContactManifold& manifold)
{
    val points = val::array();
    for (int i = 0; i < manifold.pointCount; ++i) {
        points.call<void>("push", toArray(manifold.points[static_cast<std::size_t>(i)].position));
    }
    val object = val::object();
    object.set("points", points);
    object.set("average", toArray(manifold.averagePoint()));
    object.set("normal", toArray(manifold.normal));
    return object;
}

/// For each dynamic body, the vertices touching the ground at its pose now.
val touching(const WebSimulation& simulation)
{
    val list = val::array();
    for (std::size_t i = 0; i < simulation.bodyCount(); ++i) {
        if (simulation.isStatic(i)) {
            continue;
        }
        const ContactManifold manifold =
            simulation.runner().world().contactsOf(simulation.runner().bodies()[i]);
        if (manifold.pointCount > 0) {
            val object = manifoldObject(manifold);
            object.set("body", i);
            list.call<void>("push", object);
        }
    }
    return list;
}

/// The impacts of the last step: where, and the normal and friction impulses.
val lastCollisions(const WebSimulation& simulation)
{
    val list = val::array();
    for (const CollisionEvent& event : simulation.lastCollisions()) {
        val object = manifoldObject(event.manifold);
        object.set("body", simulation.runner().bodyIndex(event.manifold.body));
        object.set("time", event.time);
        object.set("normalImpulse", toArray(event.normalImpulse));
        object.set("frictionImpulse", toArray(event.frictionImpulse));
        object.set("approachSpeed", event.approachSpeed);
        list.call<void>("push", object);
    }
    return list;
}

/// The ground height (null without one) and the static half-spaces.
val staticGeometry(const WebSimulation& simulation)
{
    val object = val::object();
    const World& world = simulation.runner().world();
    object.set("ground", world.ground() ? val(world.ground()->height) : val::null());
    val planes = val::array();
    for (const StaticPlane& plane : world.planes()) {
        val entry = val::object();
        entry.set("point", toArray(plane.point));
        entry.set("normal", toArray(plane.normal));
        planes.call<void>("push", entry);
    }
    object.set("planes", planes);
    return object;
}

void setVelocities(WebSimulation& simulation, std::size_t index, val velocity, val spin)
{
    simulation.setVelocities(index, toVec3(velocity), toVec3(spin));
}

void applyImpulse(WebSimulation& simulation, std::size_t index, val impulse, val offset,
                  const std::string& label)
{
    simulation.applyImpulse(index, toVec3(impulse), toVec3(offset), label);
}

/// {problem, impulse, offset}: problem is "" when the target is reached and the impulse
/// (applied at the offset) is applied, else why not.
val applyTarget(WebSimulation& simulation, std::size_t index, val velocity, val spin,
                const std::string& label)
{
    const ImpulseTarget solved =
        simulation.applyTarget(index, toVec3(velocity), toOptionalVec3(spin), label);
    val result = val::object();
    result.set("problem", solved.status == ImpulseTargetStatus::Reached
                              ? std::string()
                              : std::string(describe(solved.status)));
    result.set("impulse", toArray(solved.impulse));
    result.set("offset", toArray(solved.offset));
    return result;
}

// step counts cross as doubles: this Embind has no 64-bit integers without BigInt, and a double
// holds every count a run reaches exactly
double runSteps(WebSimulation& simulation, double count)
{
    return static_cast<double>(simulation.runSteps(static_cast<long long>(count)));
}

double stepCount(const WebSimulation& simulation)
{
    return static_cast<double>(simulation.stepCount());
}

double totalSteps(const WebSimulation& simulation)
{
    return static_cast<double>(simulation.totalSteps());
}

val experiments(const std::string& text, const std::string& sourceName,
                const std::string& labelPrefix)
{
    val list = val::array();
    for (const ImpulseExperiment& experiment : impulseExperiments(text, sourceName, labelPrefix)) {
        val object = val::object();
        object.set("label", experiment.label);
        object.set("startVelocity", toArray(experiment.startVelocity));
        object.set("startAngularVelocity", toArray(experiment.startAngularVelocity));
        object.set("targetVelocity", optionalArray(experiment.targetVelocity));
        object.set("targetAngularVelocity", optionalArray(experiment.targetAngularVelocity));
        object.set("impulse", toArray(experiment.impulse));
        object.set("offset", toArray(experiment.offset));
        list.call<void>("push", object);
    }
    return list;
}

} // namespace

EMSCRIPTEN_BINDINGS(tumble_web)
{
    emscripten::class_<WebSimulation>("Simulation")
        .constructor<>()
        .function("load", &WebSimulation::load)
        .function("reset", &WebSimulation::reset)
        .function("loaded", &WebSimulation::loaded)
        .function("finished", &WebSimulation::finished)
        .function("step", &WebSimulation::step)
        .function("runSteps", &runSteps)
        .function("time", &WebSimulation::time)
        .function("stepCount", &stepCount)
        .function("totalSteps", &totalSteps)
        .function("dt", &WebSimulation::dt)
        .function("duration", &WebSimulation::duration)
        .function("bodyCount", &WebSimulation::bodyCount)
        .function("bodyName", &WebSimulation::bodyName)
        .function("isStatic", &WebSimulation::isStatic)
        .function("size", &size)
        .function("state", &state)
        .function("touching", &touching)
        .function("lastCollisions", &lastCollisions)
        .function("staticGeometry", &staticGeometry)
        .function("setVelocities", &setVelocities)
        .function("applyImpulse", &applyImpulse)
        .function("applyTarget", &applyTarget)
        .function("takeLog", &WebSimulation::takeLog);
    emscripten::function("impulseExperiments", &experiments);
}

} // namespace tumble::web
