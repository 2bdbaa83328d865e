#include "console.hpp"

#include "tumble/scenario/scenario.hpp"
#include "tumble/shape.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

namespace tumble::cli {
namespace {

/// Magnitudes printed with six decimals; others with nine significant digits.
constexpr Real kFixedLow = 1e-4;
constexpr Real kFixedHigh = 1e9;

/// Components of a vector or matrix smaller than this fraction of its largest are the rounding of
/// a computation that should give zero (the x of a vertical impulse), and print as 0.000000.
constexpr Real kRelativeZero = 1e-12;

std::string formatPrintf(const char* format, Real value)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, value);
    return buffer;
}

/// The components of a vector, quaternion or matrix, formatted together: %.6f of each double
/// when the largest is from 1e-4 up to 1e9 (a component that rounds to zero prints as 0.000000,
/// never -0.000000), else %.9g of each (a 1 mg body's inverse inertia 6e+12, its impulses 6e-07),
/// with components below 1e-12 of the largest, rounding, printed as 0.
template <std::size_t N>
std::array<std::string, N> formatGroup(const std::array<Real, N>& values)
{
    Real largest = 0.0;
    for (const Real value : values) {
        largest = std::max(largest, std::fabs(value));
    }
    const bool fixed = largest == 0.0 || (largest >= kFixedLow && largest < kFixedHigh);
    std::array<std::string, N> text;
    for (std::size_t i = 0; i < N; ++i) {
        const Real value = std::fabs(values[i]) <= kRelativeZero * largest ? 0.0 : values[i];
        text[i] = fixed ? formatPrintf("%.6f", value) : formatPrintf("%.9g", value);
        if (text[i] == "-0.000000") {
            text[i] = "0.000000";
        }
    }
    return text;
}

/// "(a, b, c)" in glm::to_string's layout.
template <std::size_t N>
std::string componentList(const std::array<std::string, N>& text, std::size_t first,
                          std::size_t count)
{
    std::string list = "(";
    for (std::size_t i = first; i < first + count; ++i) {
        list += (i == first ? "" : ", ") + text[i];
    }
    return list + ")";
}

/// "1/240" when dt is the reciprocal of a whole number of steps per second, else empty.
std::string reciprocalForm(Real dt)
{
    const Real perSecond = 1.0 / dt;
    const Real rounded = std::round(perSecond);
    if (rounded < 1.0 || std::fabs(perSecond - rounded) > 1e-9 * rounded) {
        return {};
    }
    return " (1/" + formatPrintf("%.0f", rounded) + " s)";
}

std::string timePrefix(Real time) { return "t = " + formatFixed(time) + " s  "; }

} // namespace

std::string formatVec3(const Vec3& v)
{
    return "vec3" + componentList(formatGroup(std::array<Real, 3>{v.x, v.y, v.z}), 0, 3);
}

std::string formatMat3(const Mat3& m)
{
    // formatted against the largest entry of the whole matrix, printed column by column
    const std::array<std::string, 9> all = formatGroup(std::array<Real, 9>{
        m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2]});
    return "mat3x3(" + componentList(all, 0, 3) + ", " + componentList(all, 3, 3) + ", " +
           componentList(all, 6, 3) + ")";
}

namespace {

std::string formatQuat(const Quat& q)
{
    // glm::to_string's layout: quat(w, {x, y, z})
    const std::array<std::string, 4> c = formatGroup(std::array<Real, 4>{q.w, q.x, q.y, q.z});
    return "quat(" + c[0] + ", {" + c[1] + ", " + c[2] + ", " + c[3] + "})";
}

} // namespace

std::string formatFixed(Real value)
{
    // %.6f of the double where six decimals show its digits; %.9g where they would not (below
    // 1e-4 they lose digits, from 1e9 they print digits no one reads); zero of either sign is 0
    const Real magnitude = std::fabs(value);
    if (magnitude == 0.0) {
        return "0.000000";
    }
    if (magnitude < kFixedLow || magnitude >= kFixedHigh || !std::isfinite(value)) {
        return formatPrintf("%.9g", value);
    }
    return formatPrintf("%.6f", value);
}

std::string formatFull(Real value) { return formatPrintf("%.17g", value); }

const char* integratorName(Integrator integrator)
{
    switch (integrator) {
    case Integrator::Exact:
        return "exact";
    case Integrator::Handout:
        return "handout";
    }
    return "unknown";
}

const char* responseName(ContactResponse response)
{
    switch (response) {
    case ContactResponse::Sequential:
        return "sequential";
    case ContactResponse::Average:
        return "average";
    }
    return "unknown";
}

void Console::printHeader(const scenario::Runner& runner, long long stepCount) const
{
    const scenario::Scenario& scenario = runner.scenario();
    const WorldSettings& settings = runner.world().settings();
    m_out << "scenario: " << scenario.sourceName << '\n';
    m_out << "dt = " << formatPrintf("%.9g", scenario.dt) << " s" << reciprocalForm(scenario.dt)
          << ", duration = " << formatFixed(scenario.duration) << " s (" << stepCount
          << (stepCount == 1 ? " step" : " steps") << "), integrator = " << integratorName(settings.integrator)
          << ", response = " << responseName(settings.response) << '\n';
    m_out << "gravity = " << formatVec3(settings.gravity) << " m/s^2, ground: ";
    if (scenario.ground) {
        m_out << "plane y = " << formatFixed(scenario.ground->height) << " m\n";
    } else {
        m_out << "none\n";
    }
    for (std::size_t k = 0; k < scenario.planes.size(); ++k) {
        m_out << "plane " << k << ": point = " << formatVec3(scenario.planes[k].point)
              << " m, normal = " << formatVec3(scenario.planes[k].normal) << '\n';
    }

    // the handouts ask for the inverse inertia of each body, printed with glm::to_string
    for (std::size_t i = 0; i < runner.bodies().size(); ++i) {
        const Body& body = runner.world().body(runner.bodies()[i]);
        if (body.isStatic()) {
            m_out << "body " << runner.bodyName(i) << ": static, size = "
                  << formatVec3(body.shape.size) << " m, position = " << formatVec3(body.position)
                  << " m\n";
            continue;
        }
        const Vec3& inv = body.invInertiaBody;
        const Mat3 invInertiaBody(Vec3(inv.x, 0.0, 0.0), Vec3(0.0, inv.y, 0.0), Vec3(0.0, 0.0, inv.z));
        m_out << "body " << runner.bodyName(i) << ": mass = " << formatFixed(body.mass)
              << " kg, size = " << formatVec3(body.shape.size) << " m, elasticity = "
              << formatFixed(body.material.restitution) << ", friction = "
              << formatFixed(body.material.friction) << '\n';
        m_out << "  inverse inertia (body frame):  " << formatMat3(invInertiaBody) << '\n';
        m_out << "  inverse inertia (world frame): " << formatMat3(body.invInertiaWorld) << '\n';
    }
}

void Console::printStep(const scenario::Runner& runner, const scenario::StepReport& report) const
{
    if (m_quiet) {
        return;
    }
    // an impulse inside a step splits it, so events of one step are merged back into time order
    struct Entry {
        Real time;
        int kind;
        std::size_t index;
    };
    std::vector<Entry> entries;
    for (std::size_t i = 0; i < report.impulses.size(); ++i) {
        entries.push_back({report.impulses[i].time, 0, i});
    }
    for (std::size_t i = 0; i < report.collisions.size(); ++i) {
        entries.push_back({report.collisions[i].time, 1, i});
    }
    for (std::size_t i = 0; i < report.restEvents.size(); ++i) {
        entries.push_back({report.restEvents[i].time, 2, i});
    }
    std::stable_sort(entries.begin(), entries.end(),
                     [](const Entry& a, const Entry& b) { return a.time < b.time; });
    for (const Entry& entry : entries) {
        if (entry.kind == 0) {
            printImpulse(runner, report.impulses[entry.index]);
        } else if (entry.kind == 1) {
            printCollision(runner, report.collisions[entry.index]);
        } else {
            printRest(runner, report.restEvents[entry.index]);
        }
    }
}

void Console::printUnusedImpulses(const scenario::Runner& runner, Real endTime) const
{
    if (m_quiet) {
        return;
    }
    // the runner applies an impulse within 1e-9 dt of a step's start in that step
    const Real lastApplied = endTime - 1e-9 * runner.scenario().dt;
    for (const scenario::ImpulseSpec& spec : runner.scenario().impulses) {
        if (spec.at >= lastApplied) {
            m_out << "note: " << spec.label << " at t = " << formatFixed(spec.at)
                  << " s is after the end of the run and was not applied\n";
        }
    }
}

void Console::printImpulse(const scenario::Runner& runner,
                           const scenario::AppliedImpulse& event) const
{
    m_out << timePrefix(event.time) << event.label << " on " << runner.bodyName(event.bodyIndex)
          << (event.solvedFromTarget ? " (solved for target)" : "") << '\n';
    m_out << "  impulse = " << formatVec3(event.impulse) << " N s at offset "
          << formatVec3(event.offset) << " m from the centre of mass\n";
    m_out << "  velocity:         " << formatVec3(event.velocityBefore) << " -> "
          << formatVec3(event.velocityAfter) << " m/s\n";
    m_out << "  angular velocity: " << formatVec3(event.angularVelocityBefore) << " -> "
          << formatVec3(event.angularVelocityAfter) << " rad/s\n";
}

void Console::printCollision(const scenario::Runner& runner, const CollisionEvent& event) const
{
    const ContactManifold& manifold = event.manifold;
    const ContactFeature feature = manifold.feature();
    // the other side: another body (its points are pairs of features, not vertices), a plane
    // or the ground
    const bool betweenBodies = !manifold.other.isNull();
    const std::string target =
        betweenBodies         ? runner.bodyName(runner.bodyIndex(manifold.other))
        : manifold.plane >= 0 ? "plane " + std::to_string(manifold.plane)
                              : std::string("the ground");
    const char* pointWord = betweenBodies ? (manifold.pointCount == 1 ? " point" : " points")
                                          : (manifold.pointCount == 1 ? " vertex" : " vertices");
    m_out << timePrefix(event.time) << runner.bodyName(runner.bodyIndex(manifold.body)) << " hits "
          << target << " on " << (feature == ContactFeature::Edge ? "an " : "a ")
          << featureName(feature) << " (" << manifold.pointCount << pointWord << ")\n";
    for (int i = 0; i < manifold.pointCount; ++i) {
        const ContactPoint& point = manifold.points[static_cast<std::size_t>(i)];
        if (point.vertex >= 0) {
            m_out << "  vertex " << point.vertex << ": " << formatVec3(point.position) << '\n';
        } else {
            m_out << "  point " << i << ": " << formatVec3(point.position) << '\n';
        }
    }
    m_out << "  average: " << formatVec3(manifold.averagePoint())
          << ", penetration = " << formatPrintf("%.3g", manifold.maxPenetration()) << " m\n";
    m_out << "  approach speed = " << formatFixed(event.approachSpeed) << " m/s, "
          << (!event.restitutionApplied ? "no restitution (slower than the threshold)"
              : event.restitution > 0.0  ? "restitution applied"
                                         : "restitution applied with elasticity 0 (a plastic impact)")
          << '\n';
    m_out << "  normal impulse = " << formatVec3(event.normalImpulse)
          << " N s, friction impulse = " << formatVec3(event.frictionImpulse) << " N s\n";
    m_out << "  kinetic energy: " << formatFixed(event.kineticEnergyBefore) << " J -> "
          << formatFixed(event.kineticEnergyAfter) << " J\n";
}

void Console::printRest(const scenario::Runner& runner, const RestEvent& event) const
{
    m_out << runner.bodyName(runner.bodyIndex(event.body)) << " came to rest at t = "
          << formatFixed(event.time) << " s on face " << faceName(event.faceDown) << '\n';
}

void Console::printSummary(const scenario::Runner& runner) const
{
    const Vec3& gravity = runner.world().settings().gravity;
    m_out << "final state at t = " << formatFixed(runner.time()) << " s (" << runner.stepCount()
          << (runner.stepCount() == 1 ? " step" : " steps") << "):\n";
    for (std::size_t i = 0; i < runner.bodies().size(); ++i) {
        const Body& body = runner.world().body(runner.bodies()[i]);
        if (body.isStatic()) {
            continue;
        }
        const Real kinetic = body.kineticEnergy();
        const Real potential = body.potentialEnergy(gravity);
        m_out << "  " << runner.bodyName(i) << ": position = " << formatVec3(body.position)
              << ", orientation = " << formatQuat(body.orientation) << '\n';
        m_out << "    velocity = " << formatVec3(body.linearVelocity)
              << ", angular velocity = " << formatVec3(body.angularVelocity) << '\n';
        m_out << "    kinetic energy = " << formatFixed(kinetic)
              << " J, potential energy = " << formatFixed(potential)
              << " J, total = " << formatFixed(kinetic + potential) << " J"
              << (body.asleep ? ", at rest" : "") << '\n';
    }
}

} // namespace tumble::cli
