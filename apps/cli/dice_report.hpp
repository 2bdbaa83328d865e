// What `tumble throw` reports for a scenario of several dice: the counts (per-die faces, the joint
// table of the first two dice, the sum of the faces up), the console report, the summary JSON and
// the per-throw CSV (docs/dice.md).
#pragma once

#include "tumble/scenario/scenario.hpp"
#include "tumble/scenario/throw_dice.hpp"

#include <cstdint>
#include <iosfwd>
#include <span>
#include <string>
#include <vector>

namespace tumble::cli {

/// The counts of a study, in one vector of integers so MPI ranks sum them in one reduction.
/// A throw counts as unsettled when some die is not at rest by max_time; in a settled throw each
/// cocked die counts in `cocked` and not in its face table, and a throw with a cocked die is left
/// out of the joint table and the sum (a tray's rules reroll it).
class DiceCounts {
public:
    /// Empty counts for `dice` dice; `cubes` when every die is a cube (the sum is counted).
    DiceCounts(std::size_t dice, bool cubes);

    void add(std::span<const scenario::DieOutcome> throwOutcome);

    [[nodiscard]] std::size_t dice() const { return m_dice; }
    [[nodiscard]] bool cubes() const { return m_cubes; }
    [[nodiscard]] std::span<const std::int64_t> faces(std::size_t die) const;
    /// 6 x 6, row-major: row the face down of die 1, column of die 2 (empty for one die).
    [[nodiscard]] std::span<const std::int64_t> joint() const;
    /// Element s - dice counts the throws whose faces up sum to s (empty unless cubes).
    [[nodiscard]] std::span<const std::int64_t> sums() const;
    [[nodiscard]] std::int64_t unsettled() const { return m_data[m_unsettled]; }
    [[nodiscard]] std::int64_t cocked() const { return m_data[m_unsettled + 1]; }
    [[nodiscard]] std::int64_t unplaced() const { return m_data[m_unsettled + 2]; }
    /// Settled throws with no die cocked.
    [[nodiscard]] std::int64_t flatThrows() const { return m_data[m_unsettled + 3]; }
    /// Every throw added.
    [[nodiscard]] std::int64_t throws() const { return m_data[m_unsettled + 4]; }
    /// Every count, for MPI's sum.
    [[nodiscard]] std::span<std::int64_t> data() { return m_data; }

private:
    std::size_t m_dice;
    bool m_cubes;
    std::size_t m_unsettled;
    std::size_t m_joint;
    std::size_t m_sums;
    std::vector<std::int64_t> m_data;
};

/// The pips of the face opposite `faceDown`, which is up: +x 1, -x 6, +y 2, -y 5, +z 3, -z 4
/// (opposite faces add up to 7).
int pipsUp(CuboidFace faceDown);

/// Whether every die of the scenario is a cube.
bool allCubes(const scenario::Scenario& scenario);

/// The report: each die's face table (Wilson intervals, chi-square for a cube), the joint table
/// of the first two with the chi-square test of independence, the sum against the exact fair
/// distribution, and the unsettled throws and cocked dice.
void printDiceReport(std::ostream& out, const scenario::Scenario& scenario,
                     const DiceCounts& counts);

/// {"throws": N, "seed": S, "unsettled": n, "cocked": n, "dice": {"<name>": {"+x": n, ...},
/// ...}, "sum": {"<s>": n, ...}} and a newline; "sum" only for cubes. Keys in this order.
std::string diceSummaryJson(const scenario::Scenario& scenario, std::int64_t throws,
                            const DiceCounts& counts, std::uint64_t seed, bool interrupted = false);

/// One row per throw: index, sum (empty unless every die lies flat), then per die its face down
/// ("unsettled" when the throw is), cocked (0 or 1) and rest time.
void writeDiceCsv(const std::string& path, const scenario::Scenario& scenario,
                  std::span<const scenario::DieOutcome> outcomes);

} // namespace tumble::cli
