// Running a throw of several dice: the world buildWorld makes of the throw's scenario, stepped as
// `tumble run` steps it, until every die is at rest at once or maxTime has passed.
#include "tumble/scenario/throw_dice.hpp"

#include "tumble/scenario/runner.hpp"

#include "vector_length.hpp"

namespace tumble::scenario {

namespace {

/// At rest now: asleep, or (sleep off) slow for sleepTime; a die woken by a later impact is not.
bool atRest(const World& world, BodyId id)
{
    const Body& body = world.body(id);
    return body.asleep || body.slowTime >= world.settings().sleepTime;
}

} // namespace

Scenario diceScenario(const Scenario& scenario, std::span<const ThrowState> states)
{
    Scenario single = scenario;
    single.throwSpec.reset();
    single.duration = scenario.throwSpec->maxTime;
    // static geometry as a file holding it loads: its unit vectors and quaternions normalised
    // once more, so the throw and its replay start from the same bits
    for (StaticPlane& plane : single.planes) {
        plane.normal = plane.normal / detail::vectorLength(plane.normal);
    }
    for (BodySpec& body : single.bodies) {
        if (body.def.motion == BodyMotion::Static) {
            body.def.orientation = normalizedOrientation(body.def.orientation);
        }
    }
    const std::vector<std::size_t> dice = diceOf(scenario);
    for (std::size_t k = 0; k < dice.size(); ++k) {
        BodyDef& def = single.bodies[dice[k]].def;
        def.position = states[k].position;
        def.orientation = normalizedOrientation(states[k].orientation);
        def.linearVelocity = states[k].velocity;
        def.angularVelocity = states[k].angularVelocity;
    }
    return single;
}

void runDiceWorld(World& world, std::span<const BodyId> dice, Real maxTime, Real dt,
                  std::span<DieOutcome> outcomes)
{
    std::vector<Real> restTimes(dice.size(), 0.0);
    const long long stepCount = stepCountFor(maxTime, dt);
    for (long long i = 0; i < stepCount; ++i) {
        world.step(fixedStepLength(i, dt));
        bool allAtRest = true;
        for (std::size_t k = 0; k < dice.size(); ++k) {
            for (const RestEvent& rest : world.restEvents()) {
                if (rest.body.index == dice[k].index) {
                    restTimes[k] = rest.time;
                }
            }
            allAtRest = allAtRest && atRest(world, dice[k]);
        }
        if (allAtRest) {
            for (std::size_t k = 0; k < dice.size(); ++k) {
                outcomes[k] = readDieAtRest(world, dice[k]);
                outcomes[k].restTime = restTimes[k];
            }
            return;
        }
    }
    for (DieOutcome& outcome : outcomes) {
        outcome = DieOutcome{};
    }
}

void runDiceThrow(const Scenario& scenario, std::uint64_t seed, std::uint64_t index,
                  std::span<DieOutcome> outcomes)
{
    std::vector<bool> placed;
    const std::vector<ThrowState> states = drawDice(scenario, seed, index, &placed);
    for (std::size_t k = 0; k < placed.size(); ++k) {
        if (!placed[k]) {
            for (DieOutcome& outcome : outcomes) {
                outcome = DieOutcome{};
                outcome.unplaced = 1;
            }
            return;
        }
    }
    BuiltWorld built = buildWorld(diceScenario(scenario, states));
    const std::vector<std::size_t> dice = diceOf(scenario);
    std::vector<BodyId> ids;
    ids.reserve(dice.size());
    for (const std::size_t body : dice) {
        ids.push_back(built.bodies[body]);
    }
    runDiceWorld(built.world, ids, scenario.throwSpec->maxTime, scenario.dt, outcomes);
}

} // namespace tumble::scenario
