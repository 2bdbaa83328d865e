// The validation suite: cases with closed-form answers, run at any time step, and the observed
// order of convergence (docs/validation.md).
#pragma once

#include "tumble/math.hpp"
#include "tumble/world.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace tumble::validation {

/// One checked quantity of a case at one time step.
struct Quantity {
    std::string name;
    Real exact = 0.0;
    Real value = 0.0;
    /// Largest accepted |value - exact| (absolute, in the quantity's unit).
    Real tolerance = 0.0;
    std::string unit;

    [[nodiscard]] Real error() const { return std::abs(value - exact); }
    [[nodiscard]] bool passes() const { return error() <= tolerance; }
};

/// A case: a named experiment with a closed-form answer, run at a given dt.
struct Case {
    std::string name;
    /// Section of docs/validation.md that derives the exact values.
    std::string section;
    /// Order of the method for this case: 2 for the exact integrator's rotation, 1 for the
    /// handout integrator, 0 when the answer does not depend on dt (exact to rounding).
    int expectedOrder = 0;
    /// The checked quantities at time step dt; the first is the one the convergence study
    /// follows.
    std::function<std::vector<Quantity>(Real dt)> run;
};

/// Every case of the suite, in the order of docs/validation.md.
std::vector<Case> cases();

/// The time steps of the convergence study: 1/60, 1/120, 1/240, 1/480, 1/960.
std::vector<Real> convergenceSteps();

/// Least-squares slope of log(error) against log(dt) over the errors above `floor`; none when
/// fewer than two are (the case is exact to rounding).
std::optional<Real> observedOrder(const std::vector<Real>& steps, const std::vector<Real>& errors,
                                  Real floor);

/// A deliberate fault for tests that show the suite catches a wrong engine: every world the
/// cases build gets it. The default is no fault.
struct Fault {
    /// Multiplies every restitution given to a body (a solver that bounces too high or low).
    Real restitutionScale = 1.0;
    /// Replaces the integrator.
    std::optional<Integrator> integrator;
};

/// Installs `fault` for the cases run after it (test use only; not thread-safe).
void setFaultForTesting(const Fault& fault);

} // namespace tumble::validation
