// tumble: the command-line program. Declares the commands; each lives in its own file.
#include "bench_command.hpp"
#include "check_command.hpp"
#include "cli_options.hpp"
#include "console.hpp"
#include "plot_command.hpp"
#include "run_command.hpp"
#include "standard_output.hpp"
#include "throw_command.hpp"
#include "validate_command.hpp"
#include "view_command.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>

int main(int argc, char** argv)
{
    CLI::App app{"tumble: rigid cuboids falling, bouncing and sliding on a ground plane", "tumble"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("tumble ") + TUMBLE_VERSION);

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

    // a bad command line is one line "tumble: error: ..." and exit 2, as for a bad scenario;
    // help and --version print as CLI11 formats them
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& help) {
        return app.exit(help);
    } catch (const CLI::CallForAllHelp& help) {
        return app.exit(help);
    } catch (const CLI::CallForVersion& version) {
        return app.exit(version);
    } catch (const CLI::ParseError& error) {
        return tumble::cli::reportParseError(app, error, argc, argv);
    }

    // lines written stay written: a process ended by a signal loses what stdio still buffers,
    // so the console is line-buffered (not when `run --csv -` streams its CSV through stdout)
    tumble::cli::openStandardOutput(!(*run && runOptions.csvPath == "-"));
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
