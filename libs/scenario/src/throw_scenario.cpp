// One throw as an ordinary scenario: as data (throwScenario) and as TOML text that loads back to
// the same bits (throwScenarioToml, for `tumble throw --replay`).
#include "tumble/scenario/throw.hpp"

#include "toml_text.hpp"

#include <sstream>

namespace tumble::scenario {

using detail::exact;
using detail::tomlString;

Quat normalizedOrientation(const Quat& q) { return q / glm::length(q); }

Scenario throwScenario(const Scenario& scenario, const ThrowState& state)
{
    Scenario single = scenario;
    single.throwSpec.reset();
    single.duration = scenario.throwSpec->maxTime;
    BodyDef& def = single.bodies.front().def;
    def.position = state.position;
    def.orientation = normalizedOrientation(state.orientation);
    def.linearVelocity = state.velocity;
    def.angularVelocity = state.angularVelocity;
    return single;
}

std::string throwScenarioToml(const Scenario& scenario, const ThrowState& state,
                              const std::string& comment)
{
    const BodySpec& body = scenario.bodies.front();
    const BodyDef& def = body.def;
    std::ostringstream out;
    detail::writeCommentToml(out, comment);
    detail::writeWorldToml(out, scenario, scenario.throwSpec->maxTime);
    out << "\n[ground]\n"
        << "height = " << exact(scenario.ground->height) << '\n';
    // the orientation as drawn: the loader normalises it exactly as the throw did
    const Quat& q = state.orientation;
    out << "\n[[body]]\n"
        << "name = " << tomlString(body.name) << '\n'
        << "size = " << exact(def.shape.size) << '\n'
        << "mass = " << exact(def.mass) << '\n'
        << "position = " << exact(state.position) << '\n'
        << "orientation = [" << exact(q.w) << ", " << exact(q.x) << ", " << exact(q.y) << ", "
        << exact(q.z) << "]\n"
        << "velocity = " << exact(state.velocity) << '\n'
        << "angular_velocity = " << exact(state.angularVelocity) << '\n'
        << "elasticity = " << exact(def.material.restitution) << '\n'
        << "friction = " << exact(def.material.friction) << '\n';
    if (def.material.staticFriction) {
        out << "static_friction = " << exact(*def.material.staticFriction) << '\n';
    }
    return out.str();
}

} // namespace tumble::scenario
