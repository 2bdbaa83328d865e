// The counts of a study of several dice, its summary JSON and its per-throw CSV.
#include "dice_report.hpp"

#include "output_file.hpp"

#include <array>
#include <cstdio>

namespace tumble::cli {

namespace {

constexpr std::size_t kFaces = 6;

CuboidFace faceOf(const scenario::DieOutcome& outcome)
{
    return static_cast<CuboidFace>(outcome.face);
}

} // namespace

DiceCounts::DiceCounts(std::size_t dice, bool cubes)
    : m_dice(dice), m_cubes(cubes), m_unsettled(dice * kFaces),
      m_joint(m_unsettled + 5), m_sums(m_joint + (dice >= 2 ? kFaces * kFaces : 0)),
      m_data(m_sums + (cubes ? 5 * dice + 1 : 0), 0)
{
}

void DiceCounts::add(std::span<const scenario::DieOutcome> throwOutcome)
{
    ++m_data[m_unsettled + 4];
    if (throwOutcome.front().unplaced != 0) {
        ++m_data[m_unsettled + 2];
        return;
    }
    if (throwOutcome.front().settled == 0) {
        ++m_data[m_unsettled];
        return;
    }
    bool flat = true;
    int sum = 0;
    for (std::size_t k = 0; k < m_dice; ++k) {
        const scenario::DieOutcome& die = throwOutcome[k];
        if (die.cocked != 0) {
            ++m_data[m_unsettled + 1];
            flat = false;
        } else {
            ++m_data[k * kFaces + die.face];
            sum += pipsUp(faceOf(die));
        }
    }
    if (!flat) {
        return;
    }
    ++m_data[m_unsettled + 3];
    if (m_dice >= 2) {
        ++m_data[m_joint + throwOutcome[0].face * kFaces + throwOutcome[1].face];
    }
    if (m_cubes) {
        ++m_data[m_sums + static_cast<std::size_t>(sum) - m_dice];
    }
}

std::span<const std::int64_t> DiceCounts::faces(std::size_t die) const
{
    return std::span<const std::int64_t>(m_data).subspan(die * kFaces, kFaces);
}

std::span<const std::int64_t> DiceCounts::joint() const
{
    return std::span<const std::int64_t>(m_data).subspan(m_joint, m_sums - m_joint);
}

std::span<const std::int64_t> DiceCounts::sums() const
{
    return std::span<const std::int64_t>(m_data).subspan(m_sums);
}

int pipsUp(CuboidFace faceDown)
{
    // the pips of each face, in CuboidFace order; the face up is the one opposite the face down
    constexpr std::array<int, kFaces> kPips{1, 6, 2, 5, 3, 4};
    return 7 - kPips[static_cast<std::size_t>(faceDown)];
}

bool allCubes(const scenario::Scenario& scenario)
{
    for (const std::size_t body : scenario::diceOf(scenario)) {
        const Vec3& size = scenario.bodies[body].def.shape.size;
        if (size.x != size.y || size.y != size.z) {
            return false;
        }
    }
    return true;
}

std::string diceSummaryJson(const scenario::Scenario& scenario, std::int64_t throws,
                            const DiceCounts& counts, std::uint64_t seed, bool interrupted)
{
    std::string json = "{\"throws\": " + std::to_string(throws) +
                       ", \"seed\": " + std::to_string(seed) +
                       ", \"unsettled\": " + std::to_string(counts.unsettled()) +
                       ", \"cocked\": " + std::to_string(counts.cocked()) + ", \"dice\": {";
    const std::vector<std::size_t> dice = scenario::diceOf(scenario);
    for (std::size_t k = 0; k < dice.size(); ++k) {
        json += k == 0 ? "\"" : ", \"";
        json += scenario.bodies[dice[k]].name + "\": {";
        for (std::size_t face = 0; face < kFaces; ++face) {
            json += face == 0 ? "\"" : ", \"";
            json += faceName(static_cast<CuboidFace>(face));
            json += "\": " + std::to_string(counts.faces(k)[face]);
        }
        json += "}";
    }
    json += "}";
    if (counts.cubes()) {
        json += ", \"sum\": {";
        for (std::size_t s = 0; s < counts.sums().size(); ++s) {
            json += s == 0 ? "\"" : ", \"";
            json += std::to_string(s + counts.dice()) + "\": " + std::to_string(counts.sums()[s]);
        }
        json += "}";
    }
    // a run stopped by a signal counts only the throws it finished, and says so
    json += interrupted ? ", \"interrupted\": true}\n" : "}\n";
    return json;
}

void writeDiceCsv(const std::string& path, const scenario::Scenario& scenario,
                  std::span<const scenario::DieOutcome> outcomes)
{
    const std::vector<std::size_t> dice = scenario::diceOf(scenario);
    OutputFile output(path);
    std::FILE* file = output.handle();
    std::fputs("index,sum", file);
    for (const std::size_t body : dice) {
        const std::string& name = scenario.bodies[body].name;
        std::fprintf(file, ",%s_face,%s_cocked,%s_rest_time", name.c_str(), name.c_str(),
                     name.c_str());
    }
    std::fputc('\n', file);
    const bool cubes = allCubes(scenario);
    for (std::size_t i = 0; i * dice.size() < outcomes.size(); ++i) {
        const auto row = outcomes.subspan(i * dice.size(), dice.size());
        bool flat = row.front().settled != 0;
        int sum = 0;
        for (const scenario::DieOutcome& die : row) {
            flat = flat && die.cocked == 0;
            sum += pipsUp(faceOf(die));
        }
        std::fprintf(file, "%zu,", i);
        if (flat && cubes) {
            std::fprintf(file, "%d", sum);
        }
        for (const scenario::DieOutcome& die : row) {
            std::fprintf(file, ",%s,%d,", die.settled != 0 ? faceName(faceOf(die)) : "unsettled",
                         static_cast<int>(die.cocked));
            if (die.settled != 0) {
                std::fprintf(file, "%.17g", die.restTime);
            }
        }
        std::fputc('\n', file);
    }
    output.finish();
}

} // namespace tumble::cli
