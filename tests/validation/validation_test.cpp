// The validation suite itself: every case passes at dt = 1/240, the convergence orders are the
// methods', and a deliberately broken engine is caught.
#include "tumble/validation/validation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace tumble::validation {
namespace {

const Case& findCase(const std::vector<Case>& all, const std::string& name)
{
    const auto found =
        std::find_if(all.begin(), all.end(), [&](const Case& c) { return c.name == name; });
    EXPECT_NE(found, all.end()) << name;
    return *found;
}

int failures(const Case& c, Real dt)
{
    int count = 0;
    for (const Quantity& q : c.run(dt)) {
        count += q.passes() ? 0 : 1;
    }
    return count;
}

/// Restores the default (no fault) when a test ends, pass or fail.
struct FaultGuard {
    explicit FaultGuard(const Fault& fault) { setFaultForTesting(fault); }
    ~FaultGuard() { setFaultForTesting(Fault{}); }
};

TEST(Validation, EveryCasePassesAtTheDefaultStep)
{
    for (const Case& c : cases()) {
        for (const Quantity& q : c.run(1.0 / 240.0)) {
            EXPECT_TRUE(q.passes()) << c.name << ": " << q.name << " exact " << q.exact << " got "
                                    << q.value << " tolerance " << q.tolerance;
        }
    }
}

TEST(Validation, ObservedOrdersAreTheMethodsOrders)
{
    const std::vector<Real> steps = convergenceSteps();
    const std::vector<Case> all = cases();
    for (const std::string name : {"intermediate axis", "free fall, handout integrator"}) {
        const Case& c = findCase(all, name);
        std::vector<Real> errors;
        for (const Real dt : steps) {
            errors.push_back(c.run(dt).front().error());
        }
        const std::optional<Real> order = observedOrder(steps, errors, 1e-12);
        ASSERT_TRUE(order.has_value()) << name;
        EXPECT_NEAR(*order, c.expectedOrder, 0.15) << name;
    }
}

TEST(Validation, ObservedOrderOfAnExactPowerLawIsItsExponent)
{
    const std::vector<Real> steps{0.1, 0.05, 0.025};
    EXPECT_NEAR(*observedOrder(steps, {0.3, 0.075, 0.01875}, 0.0), 2.0, 1e-12);
    EXPECT_FALSE(observedOrder(steps, {1e-16, 1e-16, 1e-16}, 1e-12).has_value());
}

TEST(Validation, DoublingRestitutionIsCaught)
{
    const FaultGuard guard(Fault{.restitutionScale = 2.0});
    const std::vector<Case> all = cases();
    EXPECT_GT(failures(findCase(all, "face-down bounces"), 1.0 / 240.0), 0);
    EXPECT_GT(failures(findCase(all, "edge impact"), 1.0 / 240.0), 0);
}

TEST(Validation, TheHandoutIntegratorFailsTheTorqueFreeCases)
{
    const FaultGuard guard(Fault{.integrator = Integrator::Handout});
    const std::vector<Case> all = cases();
    EXPECT_GT(failures(findCase(all, "symmetric top"), 1.0 / 240.0), 0);
    EXPECT_GT(failures(findCase(all, "intermediate axis"), 1.0 / 240.0), 0);
    EXPECT_GT(failures(findCase(all, "free fall"), 1.0 / 240.0), 0);
}

} // namespace
} // namespace tumble::validation
