// Trajectory: the samples World.run and Scenario.run return, one row per dynamic body per sample,
// with the columns of `tumble run --csv` (time, body, x..wz, kinetic, potential) as a NumPy
// structured array.
#pragma once

#include "tumble/body_id.hpp"
#include "tumble/world.hpp"

#include <pybind11/numpy.h>

#include <cstdint>
#include <span>
#include <vector>

namespace tumble::python {

namespace py = pybind11;

/// One row: the state of one body at one time, as `tumble run --csv` writes it.
struct TrajectoryRow {
    double time;
    /// The body's index: its serial number in a tumble.World, its place in the scenario's
    /// bodies for Scenario.run.
    std::int64_t body;
    double x, y, z;
    double qw, qx, qy, qz;
    double vx, vy, vz;
    double wx, wy, wz;
    double kinetic, potential;
};

/// Registers the row's NumPy dtype; once, at module import.
void registerTrajectoryDtype();

/// Rows gathered during a run, handed to NumPy without a copy.
class Trajectory {
public:
    /// Appends one row per live dynamic body of `bodies` (static geometry never moves), with
    /// body = its index in `bodies`, at `time`.
    void sample(const World& world, std::span<const BodyId> bodies, double time);
    void reserve(std::size_t rows) { m_rows.reserve(rows); }

    /// The rows as a structured array; the Trajectory is empty afterwards.
    py::array release();

private:
    std::vector<TrajectoryRow> m_rows;
};

/// Sample steps of a run of `stepCount` steps every `every` steps: step 0, each multiple of
/// `every`, and the last step (always, as tumble run --csv ends with the final state).
[[nodiscard]] long long sampleCount(long long stepCount, long long every);

} // namespace tumble::python
