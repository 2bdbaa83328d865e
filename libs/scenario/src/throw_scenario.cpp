// One throw as an ordinary scenario: as data (throwScenario) and as TOML text that loads back to
// the same bits (throwScenarioToml, for `tumble throw --replay`).
#include "tumble/scenario/throw.hpp"

#include "schema.hpp"

#include <cstdio>
#include <sstream>

namespace tumble::scenario {

namespace {

/// %.17g: enough digits for every double to read back as itself.
std::string exact(Real value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return buffer;
}

std::string exact(const Vec3& v)
{
    // appended, not a chain of operator+ (GCC 12 warns falsely, -Wrestrict, on such chains)
    std::string text = "[";
    text += exact(v.x);
    text += ", ";
    text += exact(v.y);
    text += ", ";
    text += exact(v.z);
    text += ']';
    return text;
}

/// A TOML basic string: quotes, backslashes and control characters escaped.
std::string tomlString(const std::string& text)
{
    std::string quoted = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') {
            quoted += '\\';
            quoted += c;
        } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
            char escape[8];
            std::snprintf(escape, sizeof escape, "\\u%04x", static_cast<unsigned>(c));
            quoted += escape;
        } else {
            quoted += c;
        }
    }
    return quoted + "\"";
}

} // namespace

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
    const WorldSettings& settings = scenario.settings;
    const BodySpec& body = scenario.bodies.front();
    const BodyDef& def = body.def;
    std::ostringstream out;
    std::istringstream lines(comment);
    for (std::string line; std::getline(lines, line);) {
        out << "# " << line << '\n';
    }
    // every setting is written, defaults too, so the file does not depend on today's defaults
    out << "\n[world]\n"
        << "gravity = " << exact(settings.gravity) << '\n'
        << "dt = " << exact(scenario.dt) << '\n'
        << "duration = " << exact(scenario.throwSpec->maxTime) << '\n'
        << "integrator = \""
        << detail::kIntegratorNames[settings.integrator == Integrator::Exact ? 0 : 1] << "\"\n"
        << "response = \""
        << detail::kResponseNames[settings.response == ContactResponse::Sequential ? 0 : 1]
        << "\"\n"
        << "contact_tolerance = " << exact(settings.contactTolerance) << '\n'
        << "restitution_threshold = " << exact(settings.restitutionThreshold) << '\n'
        << "solver_iterations = " << settings.solverIterations << '\n'
        << "sleep = " << (settings.allowSleep ? "true" : "false") << '\n'
        << "sleep_linear_speed = " << exact(settings.sleepLinearSpeed) << '\n'
        << "sleep_angular_speed = " << exact(settings.sleepAngularSpeed) << '\n'
        << "sleep_time = " << exact(settings.sleepTime) << '\n';
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
