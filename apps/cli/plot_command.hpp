// `tumble plot CSV ...`: PNG plots of the CSV files `tumble run` writes, drawn by gnuplot; and the
// error-against-dt plot of `tumble validate --plot`.
#pragma once

#include "tumble/math.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace tumble::cli {

struct PlotOptions {
    std::vector<std::string> files;
    /// Folder for the PNG files; empty means next to each CSV.
    std::string outputDirectory;
    /// The body to plot; empty means every body, one curve each.
    std::string body;
};

CLI::App* addPlotCommand(CLI::App& app, PlotOptions& options);

/// Plots each file (state CSV: height, speed and spin; energy CSV: every ledger term; contacts
/// CSV: normal and friction impulses) to FILE.png. Returns the exit code.
int plotCommand(const PlotOptions& options);

/// One line of the convergence plot: a case's error at each step.
struct ConvergenceSeries {
    std::string label;
    std::vector<Real> errors;
};

/// Writes DIRECTORY/convergence.png: error against dt on log-log axes, one line per series.
void plotConvergence(const std::string& directory, const std::vector<Real>& steps,
                     const std::vector<ConvergenceSeries>& series);

} // namespace tumble::cli
