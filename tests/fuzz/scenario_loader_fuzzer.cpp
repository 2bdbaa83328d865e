// libFuzzer target: arbitrary bytes as a scenario file. The loader must either accept them or
// throw ScenarioError (no crash, hang, leak or sanitizer report); what it accepts must build a
// world that steps with a finite state. Seeded with scenarios/; dictionary scenario.dict.
// The steps are bounded by a count and a time: what a step costs varies a hundredfold with the
// scene (a dropped stack of 20 made elastic takes 0.1 s a step in a release build and fifty times
// that under the sanitizers and coverage), so a count alone would make ordinary slow scenes
// look like hangs. A single step that never ends still runs past libFuzzer's -timeout.
#include "fuzz_check.hpp"

#include "tumble/scenario/runner.hpp"
#include "tumble/scenario/scenario.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace {

/// Steps of an accepted scenario: enough to reach the first impacts of most seeds' variants.
constexpr long long kMaxSteps = 64;
/// No step starts after this much time in the unit (tools/ci-fuzz.sh gives a unit 30 s).
constexpr std::chrono::seconds kSteppingTime{2};

bool finite(const tumble::Body& body)
{
    return tumble::isFinite(body.position) && tumble::isFinite(body.orientation) &&
           tumble::isFinite(body.linearVelocity) && tumble::isFinite(body.angularVelocity);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    tumble::scenario::Scenario loaded;
    try {
        loaded = tumble::scenario::parseScenario(text, "fuzz.toml");
    } catch (const tumble::scenario::ScenarioError&) {
        return 0;
    }
    FUZZ_CHECK(!loaded.bodies.empty(), "accepted a scenario without bodies");
    try {
        tumble::scenario::Runner runner(loaded);
        const long long steps = std::min<long long>(
            kMaxSteps, static_cast<long long>(std::ceil(loaded.duration / loaded.dt)));
        const auto start = std::chrono::steady_clock::now();
        for (long long i = 0; i < steps; ++i) {
            if (i > 0 && std::chrono::steady_clock::now() - start > kSteppingTime) {
                break;
            }
            runner.step();
            for (const tumble::BodyId id : runner.bodies()) {
                FUZZ_CHECK(finite(runner.world().body(id)), "non-finite state at step %lld", i);
            }
        }
    } catch (const tumble::scenario::ScenarioError&) {
        // an unreachable target impulse stops a run with a message: fine
    }
    return 0;
}
