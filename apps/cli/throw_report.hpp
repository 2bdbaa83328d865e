// What `tumble throw` reports: the face counts, the console table (Wilson intervals, chi-square
// test), the summary JSON and the per-throw CSV.
#pragma once

#include "tumble/scenario/scenario.hpp"
#include "tumble/scenario/throw.hpp"

#include <array>
#include <cstdint>
#include <iosfwd>
#include <span>
#include <string>

namespace tumble::cli {

/// Throws that ended on each face, in CuboidFace order (+x, -x, +y, -y, +z, -z), then the
/// unsettled ones.
struct FaceCounts {
    static constexpr std::size_t kUnsettled = 6;
    std::array<std::int64_t, 7> counts{};

    [[nodiscard]] std::int64_t settled() const;
    [[nodiscard]] std::int64_t unsettled() const { return counts[kUnsettled]; }
};

FaceCounts countFaces(std::span<const scenario::ThrowOutcome> outcomes);

/// Whether the die is a cube (all three edges equal), for which every face is equally likely
/// by symmetry and the chi-square test applies.
bool isCube(const scenario::Scenario& scenario);

/// The table: face, count, probability among settled throws, 95% Wilson interval; the unsettled
/// throws; for a cube the chi-square test of uniformity with its p-value.
void printFaceTable(std::ostream& out, const scenario::Scenario& scenario, const FaceCounts& faces);

/// {"throws": N, "faces": {"+x": n, ...}, "unsettled": n, "seed": S} and a newline; the keys
/// always in this order, so runs that agree give byte-identical files.
std::string summaryJson(std::int64_t throws, const FaceCounts& faces, std::uint64_t seed,
                        bool interrupted = false);

/// Writes one CSV row per throw (the initial state is drawn again from (seed, index)) to `path`
/// through an OutputFile: index, face ("unsettled" when not at rest), rest time (empty when
/// unsettled), initial position, velocity, angular velocity and orientation (w, x, y, z as
/// drawn), every number with %.17g.
void writeThrowCsv(const std::string& path, const scenario::Scenario& scenario,
                   std::uint64_t seed, std::span<const scenario::ThrowOutcome> outcomes);

} // namespace tumble::cli
