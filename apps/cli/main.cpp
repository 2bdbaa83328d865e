// tumble: the command-line program. Declares the commands; each lives in its own file.
#include "bench_command.hpp"
#include "check_command.hpp"
#include "console.hpp"
#include "plot_command.hpp"
#include "run_command.hpp"
#include "throw_command.hpp"
#include "validate_command.hpp"
#include "view_command.hpp"

#include <CLI/CLI.hpp>

int main(int argc, char** argv)
{
    CLI::App app{"tumble: rigid cuboids falling, bouncing and sliding on a ground plane", "tumble"};
    app.require_subcommand(1);

    tumble::cli::RunOptions runOptions;
    tumble::cli::CheckOptions checkOptions;
    const CLI::App* run = tumble::cli::addRunCommand(app, runOptions);
    const CLI::App* check = tumble::cli::addCheckCommand(app, checkOptions);
    tumble::cli::ValidateOptions validateOptions;
    const CLI::App* validate = tumble::cli::addValidateCommand(app, validateOptions);
    tumble::cli::PlotOptions plotOptions;
    const CLI::App* plot = tumble::cli::addPlotCommand(app, plotOptions);
    tumble::cli::ThrowOptions throwOptions;
    const CLI::App* throwDice = tumble::cli::addThrowCommand(app, throwOptions);
    tumble::cli::BenchOptions benchOptions;
    const CLI::App* bench = tumble::cli::addBenchCommand(app, benchOptions);
    tumble::cli::ViewOptions viewOptions;
    const CLI::App* view = tumble::cli::addViewCommand(app, viewOptions);

    // CLI11 prints its own usage errors; every one of them exits with the bad-input code
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);
        return code == 0 ? tumble::cli::kExitOk : tumble::cli::kExitBadInput;
    }

    return tumble::cli::runReportingErrors([&] {
        if (*run) {
            return tumble::cli::runCommand(runOptions);
        }
        if (*throwDice) {
            return tumble::cli::throwCommand(throwOptions);
        }
        if (*validate) {
            return tumble::cli::validateCommand(validateOptions);
        }
        if (*plot) {
            return tumble::cli::plotCommand(plotOptions);
        }
        if (*bench) {
            return tumble::cli::benchCommand(benchOptions);
        }
        if (*view) {
            return tumble::cli::viewCommand(viewOptions);
        }
        return *check ? tumble::cli::checkCommand(checkOptions) : tumble::cli::kExitBadInput;
    });
}
