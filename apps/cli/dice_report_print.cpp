// The console report of a study of several dice: per-die face tables, the joint table of the
// first two dice with its test of independence, and the sum against the fair distribution.
#include "dice_report.hpp"

#include "console.hpp"

#include "tumble/scenario/dice_statistics.hpp"

#include <cinttypes>
#include <cstdio>
#include <numeric>
#include <ostream>

namespace tumble::cli {

namespace {

constexpr int kFaces = 6;
/// Confidence of the intervals in the tables.
constexpr Real kTableConfidence = 0.95;

std::string printed(const char* format, Real value)
{
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, value);
    return buffer;
}

std::string testLine(const char* what, const scenario::ChiSquareTest& test)
{
    if (test.degreesOfFreedom < 1) {
        return std::string(what) + ": n/a (too few throws lie flat)\n";
    }
    return std::string(what) + " (" + std::to_string(test.degreesOfFreedom) +
           " degrees of freedom): X^2 = " + printed("%.4f", test.statistic) + ", p = " +
           printed("%.4g", scenario::chiSquarePValue(test.statistic, test.degreesOfFreedom)) +
           '\n';
}

void printDieTable(std::ostream& out, const std::string& name, std::span<const std::int64_t> faces,
                   bool cube)
{
    const std::int64_t flat = std::accumulate(faces.begin(), faces.end(), std::int64_t{0});
    out << "die " << name << ": face  count       probability  95% interval (Wilson)\n";
    for (int i = 0; i < kFaces; ++i) {
        const std::int64_t count = faces[static_cast<std::size_t>(i)];
        const scenario::ProbabilityInterval interval =
            scenario::wilsonInterval(count, flat, kTableConfidence);
        char line[128];
        std::snprintf(line, sizeof line, "      %-4s  %-10" PRId64 "  %.6f     [%.6f, %.6f]\n",
                      faceName(static_cast<CuboidFace>(i)), count,
                      flat > 0 ? static_cast<Real>(count) / static_cast<Real>(flat) : 0.0,
                      interval.low, interval.high);
        out << line;
    }
    if (cube) {
        const Real statistic = scenario::chiSquareUniformStatistic(faces);
        out << testLine("      chi-square test of uniformity",
                        {flat > 0 ? statistic : 0.0, flat > 0 ? kFaces - 1 : 0});
    }
}

void printJoint(std::ostream& out, const std::string& first, const std::string& second,
                std::span<const std::int64_t> joint)
{
    out << "joint table (face down): rows " << first << ", columns " << second << '\n' << "      ";
    for (int j = 0; j < kFaces; ++j) {
        char header[16];
        std::snprintf(header, sizeof header, "%9s", faceName(static_cast<CuboidFace>(j)));
        out << header;
    }
    out << '\n';
    for (int i = 0; i < kFaces; ++i) {
        char label[16];
        std::snprintf(label, sizeof label, "%-6s", faceName(static_cast<CuboidFace>(i)));
        out << label;
        for (int j = 0; j < kFaces; ++j) {
            char cell[16];
            std::snprintf(cell, sizeof cell, "%9" PRId64,
                          joint[static_cast<std::size_t>(i * kFaces + j)]);
            out << cell;
        }
        out << '\n';
    }
    out << testLine("chi-square test of independence",
                    scenario::chiSquareIndependence(joint, kFaces, kFaces));
}

void printSums(std::ostream& out, std::size_t dice, std::span<const std::int64_t> sums)
{
    const std::vector<Real> fair = scenario::fairSumDistribution(static_cast<int>(dice));
    const std::int64_t total = std::accumulate(sums.begin(), sums.end(), std::int64_t{0});
    out << "sum of the faces up (pips: +x 1, +y 2, +z 3, -z 4, -y 5, -x 6)\n"
        << "sum  count       probability  fair      95% interval (Wilson)\n";
    for (std::size_t s = 0; s < sums.size(); ++s) {
        const scenario::ProbabilityInterval interval =
            scenario::wilsonInterval(sums[s], total, kTableConfidence);
        char line[128];
        std::snprintf(line, sizeof line, "%-3zu  %-10" PRId64 "  %.6f     %.6f  [%.6f, %.6f]\n",
                      s + dice, sums[s],
                      total > 0 ? static_cast<Real>(sums[s]) / static_cast<Real>(total) : 0.0,
                      fair[s], interval.low, interval.high);
        out << line;
    }
    out << testLine("chi-square test against the fair sum",
                    total > 0 ? scenario::chiSquareGoodnessOfFit(sums, fair)
                              : scenario::ChiSquareTest{});
}

} // namespace

void printDiceReport(std::ostream& out, const scenario::Scenario& scenario,
                     const DiceCounts& counts)
{
    const std::vector<std::size_t> dice = scenario::diceOf(scenario);
    for (std::size_t k = 0; k < dice.size(); ++k) {
        const Vec3& size = scenario.bodies[dice[k]].def.shape.size;
        printDieTable(out, scenario.bodies[dice[k]].name, counts.faces(k),
                      size.x == size.y && size.y == size.z);
    }
    if (dice.size() >= 2) {
        printJoint(out, scenario.bodies[dice[0]].name, scenario.bodies[dice[1]].name,
                   counts.joint());
    }
    if (counts.cubes()) {
        printSums(out, dice.size(), counts.sums());
    }
    out << "throws with every die flat: " << counts.flatThrows()
        << "; unsettled (not at rest by max_time = "
        << printed("%g", scenario.throwSpec->maxTime) << " s): " << counts.unsettled()
        << "; cocked dice (no face within " << printed("%g", scenario::kCockedDegrees)
        << " degrees of their support, rerolled): " << counts.cocked() << '\n';
    if (counts.flatThrows() == 0) {
        printWarning("no throw ended with every die flat: the tables say nothing");
    }
}

} // namespace tumble::cli
