// Running one throw to rest: its own World, the step lengths of Runner, no event kept but the
// RestEvent that ends it.
#include "tumble/scenario/throw.hpp"

#include "tumble/scenario/runner.hpp"
#include "tumble/world.hpp"

namespace tumble::scenario {

ThrowOutcome runThrow(const Scenario& scenario, const ThrowState& state)
{
    // the world as buildWorld makes it from throwScenario(scenario, state), without copying the
    // scenario: World, ground, then the one body
    World world(scenario.settings);
    world.setGround(scenario.ground);
    BodyDef def = scenario.bodies.front().def;
    def.position = state.position;
    def.orientation = normalizedOrientation(state.orientation);
    def.linearVelocity = state.velocity;
    def.angularVelocity = state.angularVelocity;
    (void)world.createBody(def);

    // the same steps as `tumble run` over a duration of maxTime; a single body, so any rest
    // event is the die's
    const Real dt = scenario.dt;
    const long long stepCount = stepCountFor(scenario.throwSpec->maxTime, dt);
    for (long long i = 0; i < stepCount; ++i) {
        world.step(fixedStepLength(i, dt));
        if (!world.restEvents().empty()) {
            const RestEvent& rest = world.restEvents().front();
            return ThrowOutcome{.settled = true, .faceDown = rest.faceDown, .restTime = rest.time};
        }
    }
    return ThrowOutcome{};
}

} // namespace tumble::scenario
