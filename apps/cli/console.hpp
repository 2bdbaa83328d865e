// Console output of the CLI: glm-style formatting of vectors and matrices, one printer per event
// kind, exit codes, and the error guard every command runs under.
#pragma once

#include "tumble/contact.hpp"
#include "tumble/math.hpp"
#include "tumble/scenario/runner.hpp"
#include "tumble/world.hpp"

#include <functional>
#include <iosfwd>
#include <string>

namespace tumble::cli {

/// Exit codes: success, an unexpected failure (I/O), a bad scenario or command line, and a
/// simulation that produced a non-finite state.
constexpr int kExitOk = 0;
constexpr int kExitFailure = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitNonFinite = 3;
/// An output file or stream that cannot be written (full disk, unwritable path); the issue asks
/// for 3, shared with the non-finite state: the run's result could not be trusted or kept.
constexpr int kExitWriteFailure = 3;
/// A run stopped by a signal: 128 + its number (130 for SIGINT, 143 for SIGTERM).
constexpr int kExitSignalBase = 128;

/// glm::to_string's layout with the double's digits: "vec3(0.150000, 0.000000, -1.000000)"; a
/// component below 1e-12 of the largest is rounding and prints as 0.000000.
std::string formatVec3(const Vec3& v);
/// The same for a matrix, column by column: "mat3x3((...), (...), (...))".
std::string formatMat3(const Mat3& m);
/// Six decimals (%.6f of the double) from 1e-4 up to 1e9, nine significant digits (%.9g) outside
/// that, "0.000000" for zero of either sign.
std::string formatFixed(Real value);
/// Shortest round-trip-safe form (%.17g), as the CSV writes numbers.
std::string formatFull(Real value);

const char* integratorName(Integrator integrator);
const char* responseName(ContactResponse response);

/// Writes the human-readable report of a run to one stream. `quiet` drops the per-event lines.
class Console {
public:
    Console(std::ostream& out, bool quiet) : m_out(out), m_quiet(quiet) {}

    /// Scenario name, step, models, and each body's inverse inertia at the start.
    void printHeader(const scenario::Runner& runner, long long stepCount) const;
    /// Every event of one step, in the order impulses, collisions, rest.
    void printStep(const scenario::Runner& runner, const scenario::StepReport& report) const;
    /// Impulses scheduled after the end of the run, which never act.
    void printUnusedImpulses(const scenario::Runner& runner, Real endTime) const;
    /// Final pose, velocities and energies of each body.
    void printSummary(const scenario::Runner& runner) const;

private:
    void printImpulse(const scenario::Runner& runner, const scenario::AppliedImpulse& event) const;
    void printCollision(const scenario::Runner& runner, const CollisionEvent& event) const;
    void printRest(const scenario::Runner& runner, const RestEvent& event) const;

    std::ostream& m_out;
    bool m_quiet;
};

/// Runs `command`, turning every exception into "tumble: error: ..." on stderr and an exit code:
/// kExitBadInput for a ScenarioError, kExitFailure for anything else.
int runReportingErrors(const std::function<int()>& command);

/// Prints "tumble: error: <message>" on stderr.
void printError(const std::string& message);

/// Prints "tumble: warning: <message>" on stderr.
void printWarning(const std::string& message);

} // namespace tumble::cli
