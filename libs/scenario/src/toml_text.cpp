// Numbers, strings and the [world] table as TOML text that reads back to the same bits.
#include "toml_text.hpp"

#include "schema.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace tumble::scenario::detail {

std::string exact(Real value)
{
    // "%.17g" writes -0 as "-0", which TOML reads as the integer 0 and so as +0: a float literal
    // keeps the sign (a sign a replayed throw must keep to repeat the throw's rounding)
    if (value == 0.0 && std::signbit(value)) {
        return "-0.0";
    }
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

std::string exact(const Quat& q)
{
    std::string text = "[";
    text += exact(q.w);
    text += ", ";
    text += exact(q.x);
    text += ", ";
    text += exact(q.y);
    text += ", ";
    text += exact(q.z);
    text += ']';
    return text;
}

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

void writeWorldToml(std::ostream& out, const Scenario& scenario, Real duration)
{
    const WorldSettings& settings = scenario.settings;
    out << "\n[world]\n"
        << "gravity = " << exact(settings.gravity) << '\n'
        << "dt = " << exact(scenario.dt) << '\n'
        << "duration = " << exact(duration) << '\n'
        << "integrator = \""
        << kIntegratorNames[settings.integrator == Integrator::Exact ? 0 : 1] << "\"\n"
        << "response = \""
        << kResponseNames[settings.response == ContactResponse::Sequential ? 0 : 1] << "\"\n"
        << "contact_tolerance = " << exact(settings.contactTolerance) << '\n'
        << "restitution_threshold = " << exact(settings.restitutionThreshold) << '\n'
        << "solver_iterations = " << settings.solverIterations << '\n'
        << "solver = \""
        << kSolverNames[settings.solver == ContactSolver::Exact ? 0 : 1] << "\"\n"
        << "soft_substeps = " << settings.softSubsteps << '\n'
        << "soft_contact_hertz = " << exact(settings.softContactHertz) << '\n'
        << "soft_damping_ratio = " << exact(settings.softDampingRatio) << '\n'
        << "soft_push_speed = " << exact(settings.softPushSpeed) << '\n'
        << "sleep = " << (settings.allowSleep ? "true" : "false") << '\n'
        << "sleep_linear_speed = " << exact(settings.sleepLinearSpeed) << '\n'
        << "sleep_angular_speed = " << exact(settings.sleepAngularSpeed) << '\n'
        << "sleep_time = " << exact(settings.sleepTime) << '\n';
}

void writeCommentToml(std::ostream& out, const std::string& comment)
{
    std::istringstream lines(comment);
    for (std::string line; std::getline(lines, line);) {
        out << "# " << line << '\n';
    }
}

} // namespace tumble::scenario::detail
