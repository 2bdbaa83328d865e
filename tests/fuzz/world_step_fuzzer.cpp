// libFuzzer target: one cuboid built from fuzzed numbers within the valid ranges (mass, size,
// orientation, velocities, dt, elasticity, friction, integrator, response) dropped on the ground
// and stepped a few hundred times. Asserts the invariants of docs/robustness.md: a finite state,
// a unit quaternion, no vertex below the plane, and (for the default exact integrator and
// sequential response, while the spin stays below 1 rad per step) energy never above the initial
// energy plus the tolerance.
#include "fuzz_check.hpp"

#include "robustness/drop_case.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace {

using tumble::Real;
using tumble::Vec3;

/// Numbers in [0, 1) from the fuzzed bytes, 8 bytes each; zeros once the bytes run out.
class FuzzedNumbers {
public:
    FuzzedNumbers(const std::uint8_t* data, std::size_t size) : m_data(data), m_size(size) {}

    Real unit()
    {
        std::uint64_t bits = 0;
        const std::size_t count = std::min<std::size_t>(8, m_size - m_used);
        if (count == 0) {
            return 0.0; // memcpy from a null pointer is undefined even for zero bytes
        }
        std::memcpy(&bits, m_data + m_used, count);
        m_used += count;
        return static_cast<Real>(bits >> 11) * 0x1.0p-53;
    }
    Real uniform(Real low, Real high) { return low + (high - low) * unit(); }
    Real logUniform(Real low, Real high)
    {
        return std::exp(uniform(std::log(low), std::log(high)));
    }
    /// The draws of a vector are separate statements: the order in which a function's arguments
    /// are evaluated is unspecified (gcc goes right to left, clang left to right), and an input
    /// must mean the same case to the clang fuzzer and to the replay in a gcc build.
    Vec3 uniformVector(const Vec3& low, const Vec3& high)
    {
        Vec3 drawn;
        for (int axis = 0; axis < 3; ++axis) {
            drawn[axis] = uniform(low[axis], high[axis]);
        }
        return drawn;
    }
    Vec3 logUniformVector(Real low, Real high)
    {
        Vec3 drawn;
        for (int axis = 0; axis < 3; ++axis) {
            drawn[axis] = logUniform(low, high);
        }
        return drawn;
    }

private:
    const std::uint8_t* m_data;
    std::size_t m_size;
    std::size_t m_used = 0;
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace tumble;
    using namespace tumble::robustness;
    FuzzedNumbers numbers(data, size);
    DropCase drop;
    drop.mass = numbers.logUniform(1e-6, 1e6);
    // Edges in [1e-3, 1e3] m with at most 1:1000 between the longest and the shortest.
    const Real shortest = numbers.logUniform(1e-3, 1.0);
    drop.size = shortest * numbers.logUniformVector(1.0, 1e3);
    drop.size[static_cast<int>(numbers.unit() * 3.0)] = shortest;
    const Real qw = numbers.uniform(-1.0, 1.0);
    const Vec3 qxyz = numbers.uniformVector(Vec3(-1.0), Vec3(1.0));
    const Quat q(qw, qxyz.x, qxyz.y, qxyz.z);
    drop.orientation = glm::length(q) > 1e-3 ? glm::normalize(q) : Quat(1.0, 0.0, 0.0, 0.0);
    drop.dt = numbers.logUniform(1e-6, 0.1);
    drop.height = numbers.logUniform(1e-9, 10.0) * glm::length(drop.size);
    // Speed up to 1000 m/s, spin up to 1000 rad/s and 0.5 rad per step (the valid ranges).
    const Vec3 direction = numbers.uniformVector(Vec3(-1.0), Vec3(1.0, 0.2, 1.0));
    drop.velocity = glm::length(direction) > 0.0
                        ? glm::normalize(direction) * numbers.logUniform(1e-3, 1e3)
                        : Vec3(0.0);
    const Vec3 axis = numbers.uniformVector(Vec3(-1.0), Vec3(1.0));
    drop.angularVelocity = glm::length(axis) > 0.0
                               ? glm::normalize(axis) * std::min(1e3, 0.5 / drop.dt) *
                                     numbers.unit()
                               : Vec3(0.0);
    drop.restitution = numbers.unit();
    drop.friction = numbers.uniform(0.0, 10.0);
    const Real mode = numbers.unit();
    drop.integrator = mode < 0.125 ? Integrator::Handout : Integrator::Exact;
    drop.response = mode >= 0.125 && mode < 0.25 ? ContactResponse::Average
                                                 : ContactResponse::Sequential;
    drop.steps = 50 + static_cast<long long>(numbers.unit() * 250.0);

    const DropOutcome outcome = runDrop(drop);
    FUZZ_CHECK(outcome.finite, "non-finite state after step %lld", outcome.steps);
    FUZZ_CHECK(outcome.quaternionUnit(), "| |q| - 1 | = %g", outcome.maxQuaternionError);
    FUZZ_CHECK(outcome.penetrationBounded(), "penetration %g m (length scale %g m)",
               outcome.maxPenetration, outcome.lengthScale);
    const bool energyHolds = drop.integrator == Integrator::Exact &&
                             drop.response == ContactResponse::Sequential &&
                             outcome.maxTurnPerStep <= 1.0;
    FUZZ_CHECK(!energyHolds || outcome.energyBounded(),
               "energy rose by %g of the energy scale %g J (tolerance %g, |w| dt up to %g)",
               outcome.maxRelativeEnergyGain, outcome.energyScale, outcome.energyTolerance(),
               outcome.maxTurnPerStep);
    return 0;
}
