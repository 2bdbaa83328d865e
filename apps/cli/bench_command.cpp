// `tumble bench`: the scenarios of docs/benchmark.md timed in tumble and in the peer engines, with
// the ratio of each peer's cost per body-step to tumble's measured in the same run.
#include "bench_command.hpp"

#include "cli_options.hpp"
#include "console.hpp"
#include "bench_dice.hpp"
#include "throw_batch.hpp"

#include "tumble/scenario/scenario.hpp"
#include "tumble/scenario/throw.hpp"

#ifdef TUMBLE_HAS_PEERS
#include "peer.hpp"
#endif

#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace tumble::cli {

namespace {

/// A row's stepping is timed again until the runs add up to this much stepping, at least
/// kLeastRuns and at most kMostRuns times, and the row reports the median: a single run of S1
/// lasts about a millisecond, and the first one in a process also pays for cold caches and page
/// faults; a large scene's single run took whatever the shared machine gave it that second (a
/// two-thread row of S4 with 1000 bodies measured 1.4 to 1.9 times the one-thread row's speed
/// from run to run, 1.87 as the best of five), and three runs let the median drop one outlier.
constexpr double kTimingBudgetSeconds = 0.5;
constexpr int kLeastRuns = 3;
constexpr int kMostRuns = 25;

/// The median of the stepping times of repeated runs: `runOnce` does one run and returns its
/// stepping time, s.
template <typename RunOnce>
double medianStepSeconds(RunOnce runOnce, int& runs)
{
    std::vector<double> times;
    double total = 0.0;
    do {
        times.push_back(runOnce());
        total += times.back();
    } while ((total < kTimingBudgetSeconds || static_cast<int>(times.size()) < kLeastRuns) &&
             static_cast<int>(times.size()) < kMostRuns);
    runs = static_cast<int>(times.size());
    std::sort(times.begin(), times.end());
    const std::size_t middle = times.size() / 2;
    return times.size() % 2 == 1 ? times[middle] : 0.5 * (times[middle - 1] + times[middle]);
}

/// One row of the table.
struct BenchRow {
    std::string scenario;
    std::string engine;
    int bodies = 0;
    /// Threads tumble used; peers step on one.
    int threads = 1;
    long steps = 0;
    /// Median stepping time over `runs` runs.
    double stepSeconds = 0.0;
    int runs = 1;
    long bodiesAtRest = 0;
    long long heapBytes = 0;
    /// Peer's ns per body-step over tumble's on one thread, for the same scenario; 0 for tumble.
    double ratio = 0.0;
    std::string note;

    [[nodiscard]] double nsPerBodyStep() const
    {
        return 1e9 * stepSeconds / (static_cast<double>(steps) * bodies);
    }
};

/// Heap bytes in use (glibc): the small-block arena plus mmapped blocks.
long long heapInUse()
{
    const struct mallinfo2 info = mallinfo2();
    return static_cast<long long>(info.uordblks + info.hblkhd);
}

long stepCount(const scenario::Scenario& loaded)
{
    return std::lround(loaded.duration / loaded.dt);
}

/// tumble on `loaded`: the world is built outside the timing, then stepped `steps` times.
BenchRow runTumble(const scenario::Scenario& loaded, const std::string& name, int threads,
                   bool sleep = true)
{
    BenchRow row;
    row.scenario = name;
    row.engine = sleep ? "tumble" : "tumble nosleep";
    row.bodies = static_cast<int>(loaded.bodies.size());
    row.threads = threads;
    row.steps = stepCount(loaded);
    scenario::Scenario configured = loaded;
    configured.settings.threads = threads;
    configured.settings.allowSleep = sleep;
    bool first = true;
    row.stepSeconds = medianStepSeconds(
        [&] {
            const long long heapBefore = heapInUse();
            scenario::BuiltWorld built = scenario::buildWorld(configured);
            const long long heapBytes = heapInUse() - heapBefore;
            const auto start = std::chrono::steady_clock::now();
            for (long i = 0; i < row.steps; ++i) {
                built.world.step(loaded.dt);
            }
            const double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (first) {
                // Every run is the same to the bit: the first one's memory and rest count.
                first = false;
                row.heapBytes = heapBytes;
                // With sleep off a body at rest stays awake; the rest test (7.1) still counts it.
                const WorldSettings& settings = built.world.settings();
                for (const BodyId id : built.bodies) {
                    const Body& body = built.world.body(id);
                    row.bodiesAtRest += body.asleep || body.slowTime >= settings.sleepTime ? 1 : 0;
                }
            }
            return seconds;
        },
        row.runs);
    return row;
}

#ifdef TUMBLE_HAS_PEERS
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
    return scene;
}

std::vector<BenchRow> runPeers(const scenario::Scenario& loaded, const std::string& name,
                               std::vector<std::string>& settingsSeen)
{
    std::vector<BenchRow> rows;
    const bench::PeerScene scene = peerScene(loaded);
    for (const std::string& peer : bench::availablePeers()) {
        BenchRow row;
        row.scenario = name;
        row.engine = peer;
        row.bodies = static_cast<int>(loaded.bodies.size());
        row.steps = scene.steps;
        try {
            // The first run's memory (later runs may reuse what it freed) and rest count.
            std::optional<bench::PeerResult> first;
            row.stepSeconds = medianStepSeconds(
                [&] {
                    const bench::PeerResult result = bench::runPeer(peer, scene);
                    if (!first) {
                        first = result;
                    }
                    return result.stepSeconds;
                },
                row.runs);
            const bench::PeerResult& result = *first;
            row.bodiesAtRest = result.bodiesAtRest;
            row.heapBytes = result.heapBytes;
            const std::string line = result.engine + ": " + result.settings;
            if (std::find(settingsSeen.begin(), settingsSeen.end(), line) == settingsSeen.end()) {
                settingsSeen.push_back(line);
            }
        } catch (const bench::PeerCapacityError& error) {
            row.note = std::string("cannot hold the scene: ") + error.what();
        }
        rows.push_back(row);
    }
    return rows;
}
#endif

/// "model name" of the first CPU in /proc/cpuinfo, or "unknown CPU".
std::string cpuModel()
{
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line)) {
        if (line.starts_with("model name")) {
            const std::size_t colon = line.find(':');
            return colon == std::string::npos ? line : line.substr(colon + 2);
        }
    }
    return "unknown CPU";
}

void printMachine()
{
    std::printf("machine: %s, %u hardware threads; compiler %s; %s build\n", cpuModel().c_str(),
                std::thread::hardware_concurrency(), __VERSION__,
#ifdef NDEBUG
                "optimised"
#else
                "debug (timings not representative)"
#endif
    );
}

void printRows(const std::vector<BenchRow>& rows)
{
    std::printf("%-4s %-14s %6s %7s %8s %5s %12s %14s %9s %11s %10s\n", "scen", "engine",
                "bodies", "threads", "steps", "runs", "us/step", "ns/body-step", "at rest",
                "bytes/body", "ratio");
    for (const BenchRow& row : rows) {
        if (!row.note.empty()) {
            std::printf("%-4s %-14s %6d %7s  %s\n", row.scenario.c_str(), row.engine.c_str(),
                        row.bodies, "-", row.note.c_str());
            continue;
        }
        char ratio[32] = "";
        if (row.ratio > 0.0) {
            std::snprintf(ratio, sizeof ratio, "%.2f", row.ratio);
        }
        std::printf("%-4s %-14s %6d %7d %8ld %5d %12.2f %14.1f %9ld %11lld %10s\n",
                    row.scenario.c_str(), row.engine.c_str(), row.bodies, row.threads, row.steps,
                    row.runs, 1e6 * row.stepSeconds / static_cast<double>(row.steps),
                    row.nsPerBodyStep(),
                    row.bodiesAtRest, row.heapBytes / std::max(1, row.bodies), ratio);
    }
}

} // namespace

CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options)
{
    CLI::App* command = app.add_subcommand(
        "bench", "Time the benchmark scenarios in tumble (and the peer engines with --peers)");
    command->add_option("--bodies", options.bodies, "Body counts of S4 (default 100,1000,4000)")
        ->delimiter(',')
        ->check(wholeNumberIn(1, 1000000));
    command->add_option("--threads", options.threads, "Thread counts for tumble (default 1,2)")
        ->delimiter(',')
        ->check(wholeNumberIn(0, kMaxThreads, " (one per core)"));
    command->add_option("--duration", options.duration, "Simulated time of each scenario, s")
        ->check(positiveNumber());
    command->add_flag("--peers", options.peers,
                      "Also run Bullet, ODE and MuJoCo (those built in) on the same bodies");
    command->add_option("--throws", options.throws,
                        "Throws of dice_cube.toml timed at each thread count (0: none)")
        ->check(wholeNumberIn(0, 100000000));
    options.scenarioDir = TUMBLE_SCENARIO_DIR;
    command->add_option("--scenarios", options.scenarioDir,
                        "Folder with part3_task4_friction.toml, s4_tumbling_cuboids.toml and "
                        "dice_cube.toml");
    return command;
}

int benchCommand(const BenchOptions& options)
{
    printMachine();
    std::vector<std::string> peerSettings;
#ifndef TUMBLE_HAS_PEERS
    if (options.peers) {
        printError("--peers: this tumble was built without the peer engines "
                   "(TUMBLE_BUILD_PEERS=OFF or no engine found)");
        return kExitBadInput;
    }
#endif
    const std::string duration = "world.duration=" + formatFull(options.duration);
    std::vector<BenchRow> rows;
    const auto addScenario = [&](const scenario::Scenario& loaded, const std::string& name) {
        const std::size_t first = rows.size();
        for (const int threads : options.threads) {
            rows.push_back(runTumble(loaded, name, threads));
        }
        // The handout drop at tumble run's default (threads = 0, one per core) beside one thread:
        // a world of one body must not pay for threads, so the ratio shows a regression such as
        // reading the core count from sysfs on every step (issue 14, item 1).
        const bool defaultRow = name == "S1";
        if (defaultRow && std::find(options.threads.begin(), options.threads.end(), 0) ==
                           options.threads.end()) {
            rows.push_back(runTumble(loaded, name, 0));
        }
        // The same with sleeping off: every body is stepped to the end, resting or not.
        rows.push_back(runTumble(loaded, name, options.threads.front(), false));
        // The reference for the ratios: tumble on one thread, or the first thread count timed.
        std::optional<double> reference;
        for (std::size_t i = first; i < rows.size(); ++i) {
            if (rows[i].engine == "tumble" && (rows[i].threads == 1 || !reference)) {
                reference = rows[i].nsPerBodyStep();
            }
        }
        // the default-threads row of a one-body scene against the one-thread row (1.00: no cost)
        for (std::size_t i = first; i < rows.size() && defaultRow; ++i) {
            if (rows[i].engine == "tumble" && rows[i].threads == 0) {
                rows[i].ratio = rows[i].nsPerBodyStep() / *reference;
            }
        }
#ifdef TUMBLE_HAS_PEERS
        if (options.peers) {
            for (BenchRow& row : runPeers(loaded, name, peerSettings)) {
                if (row.note.empty()) {
                    row.ratio = row.nsPerBodyStep() / *reference;
                }
                rows.push_back(row);
            }
        }
#endif
        std::fflush(stdout);
    };
    const std::vector<std::string> s1Overrides{duration};
    addScenario(scenario::loadScenario(options.scenarioDir + "/part3_task4_friction.toml",
                                       s1Overrides),
                "S1");
    for (const int bodies : options.bodies) {
        const std::vector<std::string> s4Overrides{duration,
                                                   "spawn[0].count=" + std::to_string(bodies)};
        addScenario(scenario::loadScenario(options.scenarioDir + "/s4_tumbling_cuboids.toml",
                                           s4Overrides),
                    "S4");
    }
    printRows(rows);
    std::printf("ratio: a peer's ns/body-step over tumble's on one thread; for tumble at threads "
                "0 (one per core, tumble run's default), its own over one thread's\n");
    for (const std::string& line : peerSettings) {
        std::printf("settings of %s\n", line.c_str());
    }
    if (options.throws > 0) {
        // Throughput of `tumble throw` (docs/dice.md): whole throws, each run until the die rests.
        const scenario::Scenario die =
            scenario::loadScenario(options.scenarioDir + "/dice_cube.toml", {});
        std::printf("%-4s %-16s %8s %7s %10s %10s %9s %14s\n", "scen", "scenario", "throws",
                    "threads", "seconds", "throws/s", "settled", "s per 100000");
        for (const int threads : options.threads) {
            printDiceRow(die, options.throws, threads > 0 ? threads : defaultThreadCount());
        }
        // two dice thrown into a walled tray: the multi-dice path, throws of both dice
        const scenario::Scenario tray =
            scenario::loadScenario(options.scenarioDir + "/dice_two_in_tray.toml", {});
        for (const int threads : options.threads) {
            printTrayRow(tray, options.throws, threads > 0 ? threads : defaultThreadCount());
        }
    }
    struct rusage usage {};
    getrusage(RUSAGE_SELF, &usage);
    std::printf("peak resident memory of this run: %ld MiB\n", usage.ru_maxrss / 1024);
    return kExitOk;
}

} // namespace tumble::cli
