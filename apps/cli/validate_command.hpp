// `tumble validate`: the validation suite's table at the chosen time steps, and the convergence
// study over dt = 1/60 ... 1/960 (docs/validation.md).
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace tumble::cli {

struct ValidateOptions {
    /// Time steps of the pass/fail table; 1/240 s when none is given.
    std::vector<double> steps;
    /// CSV of every quantity at every step, table and study alike; empty for none.
    std::string csvPath;
    /// Folder for the error-against-dt plots (gnuplot); empty for none.
    std::string plotDirectory;
    /// Print only the pass/fail table, without the convergence study.
    bool tableOnly = false;
};

CLI::App* addValidateCommand(CLI::App& app, ValidateOptions& options);

/// Returns 0 when every case passes at every table step, 1 otherwise.
int validateCommand(const ValidateOptions& options);

} // namespace tumble::cli
