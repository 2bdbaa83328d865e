// Timing of one `tumble bench` row in tumble or a peer engine: repeated runs, the median, and the
// end state of the first run.
#include "bench_runs.hpp"

#ifdef TUMBLE_HAS_PEERS
#include "peer.hpp"
#endif

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>

namespace tumble::cli {

namespace {

/// A row's stepping is timed again until the runs add up to this much stepping, at least
/// `leastRuns` and at most kMostRuns times, and the row reports the median: a single run of S1
/// lasts about a millisecond, and the first one in a process also pays for cold caches and page
/// faults; a large scene's single run took whatever the shared machine gave it that second (a
/// two-thread row of S4 with 1000 bodies measured 1.4 to 1.9 times the one-thread row's speed
/// from run to run, 1.87 as the best of five), and three runs let the median drop one outlier.
constexpr double kTimingBudgetSeconds = 0.5;
constexpr int kMostRuns = 25;

/// The median of the stepping times of repeated runs: `runOnce` does one run and returns its
/// stepping time, s.
double medianStepSeconds(const std::function<double()>& runOnce, int leastRuns, int& runs)
{
    std::vector<double> times;
    double total = 0.0;
    do {
        times.push_back(runOnce());
        total += times.back();
    } while ((total < kTimingBudgetSeconds || static_cast<int>(times.size()) < leastRuns) &&
             static_cast<int>(times.size()) < kMostRuns);
    runs = static_cast<int>(times.size());
    std::sort(times.begin(), times.end());
    const std::size_t middle = times.size() / 2;
    return times.size() % 2 == 1 ? times[middle] : 0.5 * (times[middle - 1] + times[middle]);
}

/// Heap bytes in use (glibc): the small-block arena plus mmapped blocks.
long long heapInUse()
{
    const struct mallinfo2 info = mallinfo2();
    return static_cast<long long>(info.uordblks + info.hblkhd);
}

/// Whether glibc's counters see this process's allocations: a sanitizer's allocator replaces
/// malloc and leaves every counter at zero, and then the heap is not known. (By the time a row
/// runs, glibc's malloc has served the scenario's loading from its arena.)
bool heapIsCounted()
{
    const struct mallinfo2 info = mallinfo2();
    return info.arena + info.hblkhd > 0;
}

double horizontalDistance(const Vec3& from, const Vec3& to)
{
    return std::hypot(to.x - from.x, to.z - from.z);
}

/// Bodies at rest and the largest sideways move at the end of a tumble run.
void recordEndState(const scenario::BuiltWorld& built, const std::vector<Vec3>& start,
                    BenchRow& row)
{
    // With sleep off a body at rest stays awake; the rest test (7.1) still counts it.
    const WorldSettings& settings = built.world.settings();
    for (std::size_t i = 0; i < built.bodies.size(); ++i) {
        const Body& body = built.world.body(built.bodies[i]);
        row.bodiesAtRest += body.asleep || body.slowTime >= settings.sleepTime ? 1 : 0;
        row.maxSideways = std::max(row.maxSideways, horizontalDistance(start[i], body.position));
    }
}

} // namespace

long stepCount(const scenario::Scenario& loaded)
{
    return std::lround(loaded.duration / loaded.dt);
}

BenchRow runTumble(const scenario::Scenario& loaded, const std::string& name, int threads,
                   bool sleep, int leastRuns)
{
    BenchRow row;
    row.scenario = name;
    const bool soft = loaded.settings.solver == ContactSolver::Soft;
    row.engine = std::string(soft ? "tumble soft" : "tumble") + (sleep ? "" : " nosleep");
    row.bodies = static_cast<int>(loaded.bodies.size());
    row.threads = threads;
    row.steps = stepCount(loaded);
    scenario::Scenario configured = loaded;
    configured.settings.threads = threads;
    configured.settings.allowSleep = sleep;
    bool first = true;
    const auto runOnce = [&] {
        const long long heapBefore = heapInUse();
        scenario::BuiltWorld built = scenario::buildWorld(configured);
        const long long heapBytes = heapInUse() - heapBefore;
        std::vector<Vec3> start;
        for (const BodyId id : built.bodies) {
            start.push_back(built.world.body(id).position);
        }
        // a sum of counts, one addition a step: it costs nothing beside the step
        std::size_t contactPoints = 0;
        const auto begin = std::chrono::steady_clock::now();
        for (long i = 0; i < row.steps; ++i) {
            built.world.step(loaded.dt);
            contactPoints += built.world.solverStatistics().contactPoints;
        }
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        if (first) {
            // Every run is the same to the bit: the first one's memory and end state.
            first = false;
            row.heapBytes = heapIsCounted() ? heapBytes : -1;
            row.heapBytesAtEnd = heapIsCounted() ? heapInUse() - heapBefore : -1;
            row.contactsPerStep =
                static_cast<double>(contactPoints) / static_cast<double>(std::max(1L, row.steps));
            recordEndState(built, start, row);
        }
        return seconds;
    };
    row.stepSeconds = medianStepSeconds(runOnce, leastRuns, row.runs);
    return row;
}

#ifdef TUMBLE_HAS_PEERS
namespace {

bench::PeerScene peerScene(const scenario::Scenario& loaded)
{
    bench::PeerScene scene;
    for (const scenario::BodySpec& spec : loaded.bodies) {
        const BodyDef& def = spec.def;
        bench::PeerBody body{};
        for (int k = 0; k < 3; ++k) {
            body.size[k] = def.shape.size[k];
            body.position[k] = def.position[k];
            body.velocity[k] = def.linearVelocity[k];
            body.angularVelocity[k] = def.angularVelocity[k];
            scene.gravity[k] = loaded.settings.gravity[k];
        }
        body.orientation[0] = def.orientation.w;
        body.orientation[1] = def.orientation.x;
        body.orientation[2] = def.orientation.y;
        body.orientation[3] = def.orientation.z;
        body.mass = def.mass;
        body.restitution = def.material.restitution;
        body.friction = def.material.friction;
        scene.bodies.push_back(body);
    }
    scene.groundHeight = loaded.ground ? loaded.ground->height : -1e9;
    scene.dt = loaded.dt;
    scene.steps = stepCount(loaded);
    scene.sleep = loaded.settings.allowSleep;
    scene.restitutionThreshold = loaded.settings.restitutionThreshold;
    return scene;
}

/// The largest horizontal distance of a peer's end positions from the scene's start.
double peerSideways(const bench::PeerScene& scene, const bench::PeerResult& result)
{
    double largest = 0.0;
    for (std::size_t i = 0; i < result.finalPositions.size() && i < scene.bodies.size(); ++i) {
        const double* start = scene.bodies[i].position;
        const auto& end = result.finalPositions[i];
        largest = std::max(largest, std::hypot(end[0] - start[0], end[2] - start[2]));
    }
    return largest;
}

} // namespace

namespace {

/// One peer's row on `scene` at the scene's thread count.
BenchRow runPeerRow(const std::string& peer, const bench::PeerScene& scene,
                    const std::string& name, std::vector<std::string>& settingsSeen,
                    int leastRuns)
{
    BenchRow row;
    row.scenario = name;
    row.engine = peer;
    row.bodies = static_cast<int>(scene.bodies.size());
    row.threads = scene.threads;
    row.steps = scene.steps;
    try {
        // The first run's memory (later runs may reuse what it freed) and end state.
        std::optional<bench::PeerResult> first;
        const auto runOnce = [&] {
            const bench::PeerResult result = bench::runPeer(peer, scene);
            if (!first) {
                first = result;
            }
            return result.stepSeconds;
        };
        row.stepSeconds = medianStepSeconds(runOnce, leastRuns, row.runs);
        const bench::PeerResult& result = *first;
        row.bodiesAtRest = result.bodiesAtRest;
        row.heapBytes = result.heapBytes;
        row.heapBytesAtEnd = result.heapBytesAtEnd;
        row.maxSideways = peerSideways(scene, result);
        const std::string line = result.engine + ": " + result.settings;
        if (std::find(settingsSeen.begin(), settingsSeen.end(), line) == settingsSeen.end()) {
            settingsSeen.push_back(line);
        }
    } catch (const bench::PeerCapacityError& error) {
        row.note = std::string("cannot hold the scene: ") + error.what();
    }
    return row;
}

} // namespace

std::vector<BenchRow> runPeers(const scenario::Scenario& loaded, const std::string& name,
                               std::vector<std::string>& settingsSeen,
                               const std::vector<int>& threads, int leastRuns)
{
    std::vector<BenchRow> rows;
    bench::PeerScene scene = peerScene(loaded);
    for (const std::string& peer : bench::availablePeers()) {
        scene.threads = 1;
        rows.push_back(runPeerRow(peer, scene, name, settingsSeen, leastRuns));
        if (!bench::peerRunsOnThreads(peer)) {
            continue;
        }
        // an engine with its own threads also at tumble's other thread counts, for its scaling
        for (const int count : threads) {
            if (count > 1) {
                scene.threads = count;
                rows.push_back(runPeerRow(peer, scene, name, settingsSeen, leastRuns));
            }
        }
    }
    return rows;
}
#endif

} // namespace tumble::cli
