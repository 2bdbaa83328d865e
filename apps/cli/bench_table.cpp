// The tables `tumble bench` prints.
#include "bench_table.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>

namespace tumble::cli {

namespace {

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

/// The ratio column: empty for tumble's reference rows; `format` prints the number.
std::string ratioText(const BenchRow& row, const char* format = "%.2f")
{
    char ratio[32] = "";
    if (row.ratio > 0.0) {
        std::snprintf(ratio, sizeof ratio, format, row.ratio);
    }
    return ratio;
}

/// Heap bytes per body, or "-" where the allocator does not count them (a sanitizer's).
std::string bytesPerBodyText(long long heapBytes, int bodies)
{
    return heapBytes < 0 ? std::string("-") : std::to_string(heapBytes / std::max(1, bodies));
}

/// Width of the engine column: 14 ("tumble nosleep"), or the longest peer name, so that a long one
/// (Jolt's, with its commit) does not push its row out of line.
int engineWidth(const std::vector<BenchRow>& rows)
{
    std::size_t width = 14;
    for (const BenchRow& row : rows) {
        width = std::max(width, row.engine.size());
    }
    return static_cast<int>(width);
}

} // namespace

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
    const int width = engineWidth(rows);
    std::printf("%-4s %-*s %6s %7s %8s %5s %12s %14s %9s %11s %10s\n", "scen", width, "engine",
                "bodies", "threads", "steps", "runs", "us/step", "ns/body-step", "at rest",
                "bytes/body", "ratio");
    for (const BenchRow& row : rows) {
        if (!row.note.empty()) {
            std::printf("%-4s %-*s %6d %7s  %s\n", row.scenario.c_str(), width,
                        row.engine.c_str(), row.bodies, "-", row.note.c_str());
            continue;
        }
        std::printf("%-4s %-*s %6d %7d %8ld %5d %12.2f %14.1f %9ld %11s %10s\n",
                    row.scenario.c_str(), width, row.engine.c_str(), row.bodies, row.threads, row.steps,
                    row.runs, 1e6 * row.stepSeconds / static_cast<double>(row.steps),
                    row.nsPerBodyStep(), row.bodiesAtRest,
                    bytesPerBodyText(row.heapBytes, row.bodies).c_str(), ratioText(row).c_str());
    }
}

void printContactRows(const std::vector<BenchRow>& rows)
{
    // three significant digits in the ratio: a peer can be hundreds of times faster here
    const int width = engineWidth(rows);
    std::printf("%-7s %-*s %6s %7s %6s %4s %9s %12s %13s %7s %10s %10s %8s\n", "scen", width,
                "engine", "bodies", "threads", "steps", "runs", "ms/step", "ns/body-step", "contacts/step",
                "at rest", "bytes/body", "sideways m", "ratio");
    for (const BenchRow& row : rows) {
        if (!row.note.empty()) {
            std::printf("%-7s %-*s %6d %7s  %s\n", row.scenario.c_str(), width,
                        row.engine.c_str(), row.bodies, "-", row.note.c_str());
            continue;
        }
        char contacts[32] = "-";
        if (row.contactsPerStep >= 0.0) {
            std::snprintf(contacts, sizeof contacts, "%.1f", row.contactsPerStep);
        }
        std::printf("%-7s %-*s %6d %7d %6ld %4d %9.3f %12.1f %13s %7ld %10s %10.4f %8s\n",
                    row.scenario.c_str(), width, row.engine.c_str(), row.bodies, row.threads, row.steps,
                    row.runs, 1e3 * row.stepSeconds / static_cast<double>(row.steps),
                    row.nsPerBodyStep(), contacts, row.bodiesAtRest,
                    bytesPerBodyText(row.heapBytesAtEnd, row.bodies).c_str(), row.maxSideways,
                    ratioText(row, "%.3g").c_str());
    }
}

} // namespace tumble::cli
