// One row of `tumble bench`: a scenario timed in tumble or in a peer engine, with what its end
// state says (bodies at rest, memory, contacts per step, how far bodies moved sideways).
#pragma once

#include "tumble/scenario/scenario.hpp"

#include <string>
#include <vector>

namespace tumble::cli {

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
    /// Heap in use after building the world minus before; -1 where the allocator does not count
    /// (a sanitizer's replaces glibc's malloc).
    long long heapBytes = 0;
    /// Heap in use after the last step, the world still alive, minus before building; -1 as above.
    long long heapBytesAtEnd = 0;
    /// Contact points the solver saw, averaged over the steps; negative where not known (peers).
    double contactsPerStep = -1.0;
    /// Largest horizontal (x, z) distance of any body's end position from its start, m.
    double maxSideways = 0.0;
    /// Peer's ns per body-step over tumble's on one thread, for the same scenario; 0 for tumble.
    double ratio = 0.0;
    std::string note;

    [[nodiscard]] double nsPerBodyStep() const
    {
        return 1e9 * stepSeconds / (static_cast<double>(steps) * bodies);
    }
};

/// A row is timed at least this many times (the median drops one outlier); a scene whose single
/// run takes a minute (the pyramid) asks for fewer.
constexpr int kLeastRuns = 3;

/// Steps of the scenario's duration.
long stepCount(const scenario::Scenario& loaded);

/// tumble on `loaded` with `threads` threads and sleeping as `sleep` says: the world is built
/// outside the timing, then stepped to the scenario's end, at least `leastRuns` times.
BenchRow runTumble(const scenario::Scenario& loaded, const std::string& name, int threads,
                   bool sleep, int leastRuns = kLeastRuns);

#ifdef TUMBLE_HAS_PEERS
/// Every peer engine compiled in on the same bodies, sleeping as the scenario says, on one
/// thread, and an engine that can use several (bench::peerRunsOnThreads) also at each count
/// above one in `threads`; each engine's settings line is added to `settingsSeen` once.
std::vector<BenchRow> runPeers(const scenario::Scenario& loaded, const std::string& name,
                               std::vector<std::string>& settingsSeen,
                               const std::vector<int>& threads, int leastRuns = kLeastRuns);
#endif

} // namespace tumble::cli
