// The tables `tumble bench` prints: the machine line, the S1/S4 rows and the contact scenes' rows.
#pragma once

#include "bench_runs.hpp"

#include <vector>

namespace tumble::cli {

/// One line naming the CPU, its hardware threads, the compiler and the build type.
void printMachine();

/// The table of the scenes of independent bodies (S1, S4): us per step, heap after building.
void printRows(const std::vector<BenchRow>& rows);

/// The table of the contact scenes (S5, the stack, the pyramid): ms per step, contacts per step,
/// heap at the end over bodies, and the largest sideways move of any body, m.
void printContactRows(const std::vector<BenchRow>& rows);

} // namespace tumble::cli
