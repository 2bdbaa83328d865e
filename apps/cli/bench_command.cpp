// `tumble bench`: the scenarios of docs/benchmark.md timed in tumble and in the peer engines, with
// the ratio of each peer's cost per body-step to tumble's measured in the same run.
#include "bench_command.hpp"

#include "bench_runs.hpp"
#include "bench_table.hpp"
#include "cli_options.hpp"
#include "console.hpp"
#include "bench_dice.hpp"
#include "throw_batch.hpp"

#include "tumble/scenario/scenario.hpp"
#include "tumble/scenario/throw.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace tumble::cli {

namespace {

/// A single run of the pyramid or of S5 steps for one to two minutes in tumble today: one run
/// per row, so that `--scenes S5,pyramid` stays a matter of minutes with the peers.
constexpr int kSlowSceneLeastRuns = 1;

/// The scenes `--scenes` accepts; S5 and the pyramid are left out of the default.
const std::vector<std::string> kSceneNames{"S1", "S4", "S5", "stack20", "pyramid"};

/// The rows of one run and what they share.
struct BenchTables {
    std::vector<BenchRow> independent;
    std::vector<BenchRow> contact;
    std::vector<std::string> peerSettings;
};

/// The overrides every scenario gets: the simulated time, when --duration is given, then those
/// of --set.
std::vector<std::string> sceneOverrides(const BenchOptions& options)
{
    std::vector<std::string> overrides;
    if (options.duration > 0.0) {
        overrides.push_back("world.duration=" + formatFull(options.duration));
    }
    overrides.insert(overrides.end(), options.overrides.begin(), options.overrides.end());
    return overrides;
}

/// tumble's ns per body-step on one thread (or the first thread count timed) among
/// rows[first..], sleeping as `sleep` says: what the ratios are taken against.
double referenceNs(const std::vector<BenchRow>& rows, std::size_t first, bool sleep)
{
    const std::string engine = sleep ? "tumble" : "tumble nosleep";
    std::optional<double> reference;
    for (std::size_t i = first; i < rows.size(); ++i) {
        if (rows[i].engine == engine && (rows[i].threads == 1 || !reference)) {
            reference = rows[i].nsPerBodyStep();
        }
    }
    return reference.value_or(0.0);
}

#ifdef TUMBLE_HAS_PEERS
/// referenceNs at `threads` threads: tumble's row at that count among rows[first..], else the
/// one-thread reference.
double referenceNsAt(const std::vector<BenchRow>& rows, std::size_t first, bool sleep,
                     int threads)
{
    const std::string engine = sleep ? "tumble" : "tumble nosleep";
    for (std::size_t i = first; i < rows.size(); ++i) {
        if (rows[i].engine == engine && rows[i].threads == threads) {
            return rows[i].nsPerBodyStep();
        }
    }
    return referenceNs(rows, first, sleep);
}
#endif

/// The peers' rows of a scene appended to `rows`, each with its ratio to tumble's row
/// (sleeping as `sleep` says) at the peer row's thread count. Without the peers built in,
/// benchCommand refuses --peers before any scene runs.
void addPeerRows([[maybe_unused]] const scenario::Scenario& loaded,
                 [[maybe_unused]] const std::string& name, [[maybe_unused]] std::size_t first,
                 [[maybe_unused]] bool sleep, [[maybe_unused]] const BenchOptions& options,
                 [[maybe_unused]] int leastRuns, [[maybe_unused]] BenchTables& tables,
                 [[maybe_unused]] std::vector<BenchRow>& rows)
{
#ifdef TUMBLE_HAS_PEERS
    for (BenchRow& row :
         runPeers(loaded, name, tables.peerSettings, options.threads, leastRuns)) {
        const double reference = referenceNsAt(rows, first, sleep, row.threads);
        if (row.note.empty() && reference > 0.0) {
            row.ratio = row.nsPerBodyStep() / reference;
        }
        rows.push_back(row);
    }
#endif
}

/// A scene of bodies that only touch the ground (S1, S4): tumble at each thread count with
/// sleeping on, once with it off, then the peers.
void addIndependentScene(const scenario::Scenario& loaded, const std::string& name,
                         const BenchOptions& options, BenchTables& tables)
{
    std::vector<BenchRow>& rows = tables.independent;
    const std::size_t first = rows.size();
    for (const int threads : options.threads) {
        rows.push_back(runTumble(loaded, name, threads, true));
    }
    // The handout drop at tumble run's default (threads = 0, one per core) beside one thread:
    // a world of one body must not pay for threads, so the ratio shows a regression such as
    // reading the core count from sysfs on every step (issue 14, item 1).
    const bool defaultRow = name == "S1";
    if (defaultRow && std::find(options.threads.begin(), options.threads.end(), 0) ==
                          options.threads.end()) {
        rows.push_back(runTumble(loaded, name, 0, true));
    }
    // The same with sleeping off: every body is stepped to the end, resting or not.
    rows.push_back(runTumble(loaded, name, options.threads.front(), false));
    const double reference = referenceNs(rows, first, true);
    // the default-threads row of a one-body scene against the one-thread row (1.00: no cost)
    for (std::size_t i = first; i < rows.size() && defaultRow; ++i) {
        if (rows[i].engine == "tumble" && rows[i].threads == 0) {
            rows[i].ratio = rows[i].nsPerBodyStep() / reference;
        }
    }
    if (options.peers) {
        addPeerRows(loaded, name, first, true, options, kLeastRuns, tables, rows);
    }
    std::fflush(stdout);
}

/// A scene of bodies pressing on each other (S5, the stack, the pyramid): tumble at each thread
/// count with the file's sleeping, once more with sleeping off where the file has it on, the
/// soft step at each thread count, then the peers with the file's sleeping.
void addContactScene(const scenario::Scenario& loaded, const std::string& name,
                     const BenchOptions& options, int leastRuns, BenchTables& tables)
{
    std::vector<BenchRow>& rows = tables.contact;
    const std::size_t first = rows.size();
    const bool sleep = loaded.settings.allowSleep;
    for (const int threads : options.threads) {
        rows.push_back(runTumble(loaded, name, threads, sleep, leastRuns));
    }
    if (sleep) {
        rows.push_back(runTumble(loaded, name, options.threads.front(), false, leastRuns));
    }
    // the same bodies with the soft step (docs/physics/12-soft-step.md), the file's sleeping
    if (loaded.settings.solver == ContactSolver::Exact) {
        scenario::Scenario soft = loaded;
        soft.settings.solver = ContactSolver::Soft;
        for (const int threads : options.threads) {
            rows.push_back(runTumble(soft, name, threads, sleep, leastRuns));
        }
    }
    if (options.peers) {
        addPeerRows(loaded, name, first, sleep, options, leastRuns, tables, rows);
    }
    std::fflush(stdout);
}

bool wanted(const BenchOptions& options, const std::string& scene)
{
    return std::find(options.scenes.begin(), options.scenes.end(), scene) !=
           options.scenes.end();
}

/// Every scene `--scenes` names, in the order of kSceneNames.
BenchTables runScenes(const BenchOptions& options)
{
    BenchTables tables;
    const std::vector<std::string> overrides = sceneOverrides(options);
    const auto load = [&](const std::string& path, std::vector<std::string> extra = {}) {
        extra.insert(extra.begin(), overrides.begin(), overrides.end());
        return scenario::loadScenario(path, extra);
    };
    const std::string& dir = options.scenarioDir;
    if (wanted(options, "S1")) {
        addIndependentScene(load(dir + "/part3_task4_friction.toml"), "S1", options, tables);
    }
    for (const int bodies : wanted(options, "S4") ? options.bodies : std::vector<int>{}) {
        const std::string count = "spawn[0].count=" + std::to_string(bodies);
        addIndependentScene(load(dir + "/s4_tumbling_cuboids.toml", {count}), "S4", options,
                            tables);
    }
    if (wanted(options, "S5")) {
        addContactScene(load(dir + "/pile_100.toml"), "S5", options, kSlowSceneLeastRuns,
                        tables);
    }
    if (wanted(options, "stack20")) {
        addContactScene(load(dir + "/stack_20.toml"), "stack20", options, kLeastRuns, tables);
    }
    if (wanted(options, "pyramid")) {
        addContactScene(load(options.benchSceneDir + "/pyramid_1240.toml"), "pyramid", options,
                        kSlowSceneLeastRuns, tables);
    }
    return tables;
}

} // namespace

CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options)
{
    CLI::App* command = app.add_subcommand(
        "bench", "Time the benchmark scenarios in tumble (and the peer engines with --peers)");
    command->add_option("--scenes", options.scenes,
                        "Scenes to time (default S1,S4,stack20; S5 and pyramid take minutes)")
        ->delimiter(',')
        ->check(CLI::IsMember(kSceneNames));
    command->add_option("--bodies", options.bodies, "Body counts of S4 (default 100,1000,4000)")
        ->delimiter(',')
        ->check(wholeNumberIn(1, 1000000));
    command->add_option("--threads", options.threads, "Thread counts for tumble, and for a peer with threads of its own (Jolt) (default 1,2)")
        ->delimiter(',')
        ->check(wholeNumberIn(0, kMaxThreads, " (one per core)"));
    command->add_option("--duration", options.duration,
                        "Simulated time of each scenario, s (default: each file's own)")
        ->check(positiveNumber());
    command->add_option("--set", options.overrides,
                        "Override a value of every scenario timed, KEY=VALUE "
                        "(world.solver_iterations=10); repeatable")
        ->type_name("KEY=VALUE");
    command->add_flag("--peers", options.peers,
                      "Also run Bullet, ODE and MuJoCo (those built in) on the same bodies");
    command->add_option("--throws", options.throws,
                        "Throws of dice_cube.toml timed at each thread count (0: none)")
        ->check(wholeNumberIn(0, 100000000));
    options.scenarioDir = TUMBLE_SCENARIO_DIR;
    command->add_option("--scenarios", options.scenarioDir,
                        "Folder with part3_task4_friction.toml, s4_tumbling_cuboids.toml, "
                        "pile_100.toml, stack_20.toml and dice_cube.toml");
    options.benchSceneDir = TUMBLE_BENCH_SCENE_DIR;
    command->add_option("--bench-scenes", options.benchSceneDir,
                        "Folder with pyramid_1240.toml");
    return command;
}

int benchCommand(const BenchOptions& options)
{
    printMachine();
#ifndef TUMBLE_HAS_PEERS
    if (options.peers) {
        printError("--peers: this tumble was built without the peer engines "
                   "(TUMBLE_BUILD_PEERS=OFF or no engine found)");
        return kExitBadInput;
    }
#endif
    for (const std::string& override : options.overrides) {
        std::printf("every scenario with --set %s\n", override.c_str());
    }
    const BenchTables tables = runScenes(options);
    if (!tables.independent.empty()) {
        printRows(tables.independent);
    }
    if (!tables.contact.empty()) {
        printContactRows(tables.contact);
    }
    std::printf("ratio: a peer's ns/body-step over tumble's default solver at the peer's thread "
                "count (with the scene's sleeping); for tumble at threads 0 (one per core, tumble "
                "run's default), its own over one thread's\n");
    for (const std::string& line : tables.peerSettings) {
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
