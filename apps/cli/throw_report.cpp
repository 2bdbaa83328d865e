// What `tumble throw` reports: the face counts, the console table (Wilson intervals, chi-square
// test), the summary JSON and the per-throw CSV.
#include "throw_report.hpp"

#include "console.hpp"
#include "output_file.hpp"

#include "tumble/scenario/dice_statistics.hpp"
#include "tumble/shape.hpp"

#include <cinttypes>
#include <cstdio>
#include <numeric>
#include <ostream>

namespace tumble::cli {
namespace {

constexpr int kFaceCount = 6;
/// Confidence of the intervals in the table.
constexpr Real kTableConfidence = 0.95;

std::string printed(const char* format, Real value)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, value);
    return buffer;
}

CuboidFace faceAt(int index) { return static_cast<CuboidFace>(index); }

} // namespace

std::int64_t FaceCounts::settled() const
{
    return std::accumulate(counts.begin(), counts.begin() + kFaceCount, std::int64_t{0});
}

FaceCounts countFaces(std::span<const scenario::ThrowOutcome> outcomes)
{
    FaceCounts faces;
    for (const scenario::ThrowOutcome& outcome : outcomes) {
        ++faces.counts[outcome.settled ? static_cast<std::size_t>(outcome.faceDown)
                                       : FaceCounts::kUnsettled];
    }
    return faces;
}

bool isCube(const scenario::Scenario& scenario)
{
    const Vec3& size = scenario.bodies.front().def.shape.size;
    return size.x == size.y && size.y == size.z;
}

void printFaceTable(std::ostream& out, const scenario::Scenario& scenario, const FaceCounts& faces)
{
    const std::int64_t settled = faces.settled();
    out << "face  count       probability  95% interval (Wilson)\n";
    for (int i = 0; i < kFaceCount; ++i) {
        const std::int64_t count = faces.counts[static_cast<std::size_t>(i)];
        const Real probability =
            settled > 0 ? static_cast<Real>(count) / static_cast<Real>(settled) : 0.0;
        const scenario::ProbabilityInterval interval =
            scenario::wilsonInterval(count, settled, kTableConfidence);
        char line[128];
        std::snprintf(line, sizeof line, "%-4s  %-10" PRId64 "  %.6f     [%.6f, %.6f]\n",
                      faceName(faceAt(i)), count, probability, interval.low, interval.high);
        out << line;
    }
    out << "settled: " << settled << " of " << settled + faces.unsettled()
        << " throws; unsettled (not at rest by max_time = "
        << printed("%g", scenario.throwSpec->maxTime) << " s): " << faces.unsettled() << '\n';
    if (isCube(scenario) && settled == 0) {
        out << "chi-square test of uniformity: n/a (no throw settled)\n";
        printWarning("no throw came to rest within max_time: the faces say nothing");
    } else if (isCube(scenario)) {
        const std::span<const std::int64_t> faceCounts(faces.counts.data(), kFaceCount);
        const Real statistic = scenario::chiSquareUniformStatistic(faceCounts);
        out << "chi-square test of uniformity (cube, " << kFaceCount - 1
            << " degrees of freedom): X^2 = " << printed("%.4f", statistic)
            << ", p = " << printed("%.4g", scenario::chiSquarePValue(statistic, kFaceCount - 1))
            << '\n';
    }
}

std::string summaryJson(std::int64_t throws, const FaceCounts& faces, std::uint64_t seed,
                        bool interrupted)
{
    std::string json = "{\"throws\": " + std::to_string(throws) + ", \"faces\": {";
    for (int i = 0; i < kFaceCount; ++i) {
        json += i == 0 ? "\"" : ", \"";
        json += faceName(faceAt(i));
        json += "\": ";
        json += std::to_string(faces.counts[static_cast<std::size_t>(i)]);
    }
    json += "}, \"unsettled\": " + std::to_string(faces.unsettled());
    json += ", \"seed\": " + std::to_string(seed);
    // a run stopped by a signal counts only the throws it finished, and says so
    json += interrupted ? ", \"interrupted\": true}\n" : "}\n";
    return json;
}

void writeThrowCsv(const std::string& path, const scenario::Scenario& scenario,
                   std::uint64_t seed, std::span<const scenario::ThrowOutcome> outcomes)
{
    OutputFile output(path);
    std::FILE* file = output.handle();
    std::fputs("index,face,rest_time,x,y,z,vx,vy,vz,wx,wy,wz,qw,qx,qy,qz\n", file);
    for (std::size_t i = 0; i < outcomes.size(); ++i) {
        const scenario::ThrowOutcome& outcome = outcomes[i];
        const scenario::ThrowState state = scenario::drawThrow(scenario, seed, i);
        const Vec3& p = state.position;
        const Vec3& v = state.velocity;
        const Vec3& w = state.angularVelocity;
        const Quat& q = state.orientation;
        std::fprintf(file, "%zu,%s,", i, outcome.settled ? faceName(outcome.faceDown) : "unsettled");
        if (outcome.settled) {
            std::fprintf(file, "%.17g", outcome.restTime);
        }
        std::fprintf(file,
                     ",%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,"
                     "%.17g\n",
                     p.x, p.y, p.z, v.x, v.y, v.z, w.x, w.y, w.z, q.w, q.x, q.y, q.z);
    }
    output.finish();
}

} // namespace tumble::cli
