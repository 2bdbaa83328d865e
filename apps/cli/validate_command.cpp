#include "validate_command.hpp"

#include "cli_options.hpp"
#include "console.hpp"
#include "output_file.hpp"
#include "plot_command.hpp"
#include "progress_bar.hpp"

#include "tumble/validation/validation.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <unistd.h>

namespace tumble::cli {
namespace {

/// An observed order with two decimals; a slope within rounding of zero prints as 0.00.
std::string formatOrder(Real order)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", std::abs(order) < 0.005 ? 0.0 : order);
    return text;
}


std::string stepName(Real dt)
{
    const long long perSecond = std::llround(1.0 / dt);
    if (std::abs(1.0 / static_cast<Real>(perSecond) - dt) < 1e-15) {
        return "1/" + std::to_string(perSecond);
    }
    return formatFull(dt);
}

std::string formatShort(Real value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.10g", value);
    return buffer;
}

std::string formatError(Real value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2e", value);
    return buffer;
}

std::string padded(const std::string& text, std::size_t width)
{
    return text.size() >= width ? text + " " : text + std::string(width - text.size(), ' ');
}

/// Errors at or below this are rounding, not method error.
Real roundingFloor(const validation::Quantity& quantity)
{
    return 1e-11 * std::max(1.0, std::abs(quantity.exact));
}

/// Writes the CSV, whole or not at all; nothing when no path was given.
void writeCsv(const std::string& path, const std::string& text)
{
    if (path.empty()) {
        return;
    }
    OutputFile file(path);
    std::fputs(text.c_str(), file.handle());
    file.finish();
}

struct StudyRow {
    std::string caseName;
    std::string quantityName;
    int expectedOrder = 0;
    std::vector<Real> errors;
    std::optional<Real> order;
};

/// The options that cannot be run, as exit 2: a step that does not divide a second, and --plot
/// with --no-study.
void checkOptions(const ValidateOptions& options)
{
    // the plot is of the convergence study, so it cannot go with the table alone
    if (options.tableOnly && !options.plotDirectory.empty()) {
        throw UsageError("--plot", "the plot draws the convergence study, which --no-study leaves "
                                   "out; give one or the other");
    }
    // the cases compare at whole seconds (free fall at t = 1 s, sliding for 3 s, ...): a step that
    // does not divide a second compared at a time it never simulated (issue 14, item 6)
    for (const Real dt : options.steps) {
        const Real perSecond = 1.0 / dt;
        if (std::fabs(perSecond - std::round(perSecond)) > 1e-9 * perSecond) {
            throw UsageError("--dt", "the validation cases compare at whole seconds, so dt must "
                                     "be 1/n s for a whole number n (0.025 = 1/40, 0.01 = 1/100), "
                                     "got " + formatShort(dt) + " = 1/" + formatShort(perSecond));
        }
    }
}

} // namespace

CLI::App* addValidateCommand(CLI::App& app, ValidateOptions& options)
{
    CLI::App* command = app.add_subcommand(
        "validate", "Run the validation suite: tumble against closed-form mechanics");
    command->add_option("--dt", options.steps, "Time step of the pass/fail table, s (repeatable)")
        ->type_name("S")
        ->check(positiveNumber());
    command->add_option("--csv", options.csvPath, "Write every quantity at every step to CSV")
        ->type_name("PATH");
    command->add_option("--plot", options.plotDirectory,
                        "Write error-against-dt plots (PNG, gnuplot) into this folder")
        ->type_name("DIR");
    command->add_flag("--no-study", options.tableOnly,
                      "Print only the pass/fail table, not the convergence study");
    return command;
}

int validateCommand(const ValidateOptions& options)
{
    checkOptions(options);
    const std::vector<Real> tableSteps =
        options.steps.empty() ? std::vector<Real>{1.0 / 240.0} : options.steps;
    const std::vector<Real> studySteps = validation::convergenceSteps();
    const std::vector<validation::Case> cases = validation::cases();
    std::ostringstream csv;
    csv << "case,quantity,dt,exact,value,error,tolerance,pass\n";
    const auto csvRow = [&](const validation::Case& c, const validation::Quantity& q, Real dt) {
        csv << '"' << c.name << "\",\"" << q.name << "\"," << formatFull(dt) << ','
            << formatFull(q.exact) << ',' << formatFull(q.value) << ',' << formatFull(q.error())
            << ',' << formatFull(q.tolerance) << ',' << (q.passes() ? "pass" : "FAIL") << '\n';
    };

    std::ostream& out = std::cout;
    int failures = 0;
    int checks = 0;
    for (const Real dt : tableSteps) {
        out << "validation at dt = " << stepName(dt) << " s\n";
        out << padded("case", 30) << padded("quantity", 34) << padded("exact", 18)
            << padded("tumble", 18) << padded("error", 10) << padded("tolerance", 10) << "result\n";
        for (const validation::Case& c : cases) {
            for (const validation::Quantity& q : c.run(dt)) {
                ++checks;
                failures += q.passes() ? 0 : 1;
                out << padded(c.name, 30) << padded(q.name, 34)
                    << padded(formatShort(q.exact), 18) << padded(formatShort(q.value), 18)
                    << padded(formatError(q.error()), 10) << padded(formatError(q.tolerance), 10)
                    << (q.passes() ? "pass" : "FAIL") << "  " << q.unit << '\n';
                csvRow(c, q, dt);
            }
        }
        out << '\n';
    }

    if (options.tableOnly) {
        writeCsv(options.csvPath, csv.str());
        out << checks - failures << " passed, " << failures << " failed\n";
        return failures == 0 ? kExitOk : kExitFailure;
    }
    out << "convergence: error of each case's first quantity\n" << padded("case", 30);
    for (const Real dt : studySteps) {
        out << padded(stepName(dt), 10);
    }
    out << "observed order (method)\n";
    std::vector<StudyRow> study;
    // a bar on stderr over the study's runs when it is a terminal (issue 14, item 15)
    const bool progress = isatty(STDERR_FILENO) != 0;
    const auto runs = static_cast<std::int64_t>(cases.size() * studySteps.size());
    ProgressBar bar(runs, runs, "runs");
    std::int64_t done = 0;
    for (const validation::Case& c : cases) {
        StudyRow row{c.name, "", c.expectedOrder, {}, std::nullopt};
        Real floor = 0.0;
        for (const Real dt : studySteps) {
            const std::vector<validation::Quantity> quantities = c.run(dt);
            for (const validation::Quantity& q : quantities) {
                csvRow(c, q, dt);
            }
            row.quantityName = quantities.front().name;
            row.errors.push_back(quantities.front().error());
            floor = roundingFloor(quantities.front());
            if (progress) {
                bar.update(++done);
            }
        }
        if (progress) {
            ProgressBar::clear();
        }
        row.order = validation::observedOrder(studySteps, row.errors, floor);
        out << padded(c.name, 30);
        for (const Real error : row.errors) {
            out << padded(formatError(error), 10);
        }
        out << (row.order ? formatOrder(*row.order) : std::string("exact to rounding"))
            << " (" << (c.expectedOrder == 0 ? std::string("exact") : std::to_string(c.expectedOrder))
            << ")\n";
        study.push_back(row);
    }
    out << '\n' << checks - failures << " passed, " << failures << " failed\n";

    writeCsv(options.csvPath, csv.str());
    if (!options.plotDirectory.empty()) {
        std::vector<ConvergenceSeries> series;
        for (const StudyRow& row : study) {
            series.push_back({row.caseName + ": " + row.quantityName, row.errors});
        }
        plotConvergence(options.plotDirectory, studySteps, series);
    }
    return failures == 0 ? kExitOk : kExitFailure;
}

} // namespace tumble::cli
