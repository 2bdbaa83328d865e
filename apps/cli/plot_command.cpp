#include "plot_command.hpp"

#include "cli_options.hpp"
#include "console.hpp"
#include "output_file.hpp"

#include "tumble/scenario/scenario.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <vector>

extern char** environ;

namespace tumble::cli {
namespace {

/// Bodies drawn as separate curves in one plot; above this, --body must pick one.
constexpr std::size_t kMostCurves = 12;

/// Runs gnuplot without a shell (posix_spawnp with an argument vector), feeding it `script` on
/// standard input, so no file name is ever parsed by a shell; its standard output, where the
/// image goes, is `image`. Throws with the real reason.
void runGnuplot(const std::string& script, int image)
{
    int pipeEnds[2];
    if (pipe(pipeEnds) != 0) {
        throw std::runtime_error(std::string("cannot run gnuplot: pipe: ") + std::strerror(errno));
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipeEnds[0], STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&actions, image, STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&actions, pipeEnds[0]);
    posix_spawn_file_actions_addclose(&actions, pipeEnds[1]);
    char program[] = "gnuplot";
    char* const argv[] = {program, nullptr};
    pid_t child = 0;
    const int spawnError = posix_spawnp(&child, program, &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    close(pipeEnds[0]);
    if (spawnError != 0) {
        close(pipeEnds[1]);
        throw std::runtime_error(std::string("cannot run gnuplot: ") + std::strerror(spawnError) +
                                 (spawnError == ENOENT ? " (install the Debian package "
                                                         "gnuplot-nox: bash tools/install-deps.sh)"
                                                       : ""));
    }
    // a gnuplot that stops reading early must not kill tumble with SIGPIPE
    const auto previous = std::signal(SIGPIPE, SIG_IGN);
    std::size_t written = 0;
    while (written < script.size()) {
        const ssize_t count = write(pipeEnds[1], script.data() + written, script.size() - written);
        if (count < 0 && errno == EINTR) {
            continue;
        }
        if (count <= 0) {
            break;
        }
        written += static_cast<std::size_t>(count);
    }
    close(pipeEnds[1]);
    std::signal(SIGPIPE, previous);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFSIGNALED(status)) {
        throw std::runtime_error("gnuplot was ended by signal " + std::to_string(WTERMSIG(status)));
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        throw std::runtime_error("gnuplot failed with exit status " +
                                 std::to_string(WEXITSTATUS(status)) +
                                 " (its message is above)");
    }
}

std::string quoted(const std::string& text)
{
    // gnuplot's single-quoted strings take everything literally except '', a single quote
    std::string escaped;
    for (const char c : text) {
        escaped += (c == '\'' ? std::string("''") : std::string(1, c));
    }
    return "'" + escaped + "'";
}

/// The fields of one CSV line as tumble writes them (a field is quoted when it has a comma or a
/// quote, quotes doubled inside).
std::vector<std::string> csvFields(const std::string& line)
{
    std::vector<std::string> fields(1);
    bool inQuotes = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (inQuotes) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                fields.back() += '"';
                ++i;
            } else if (c == '"') {
                inQuotes = false;
            } else {
                fields.back() += c;
            }
        } else if (c == '"') {
            inQuotes = true;
        } else if (c == ',') {
            fields.emplace_back();
        } else if (c != '\r') {
            fields.back() += c;
        }
    }
    return fields;
}

/// A CSV written by `tumble run`: its header and each body's rows, in order of first appearance,
/// with the body field replaced by the body's index so gnuplot reads only numbers and words.
struct TumbleCsv {
    std::string header;
    std::vector<std::string> bodies;
    std::vector<std::string> rows;
};

TumbleCsv readTumbleCsv(const std::filesystem::path& path)
{
    std::ifstream file(path);
    if (!file) {
        throw scenario::ScenarioError({path.string(), 0}, "",
                                      std::string("cannot open CSV: ") + std::strerror(errno));
    }
    TumbleCsv csv;
    if (!std::getline(file, csv.header)) {
        throw scenario::ScenarioError({path.string(), 1}, "", "the file is empty, not a CSV "
                                                              "written by tumble run");
    }
    std::map<std::string, std::size_t> indexOf;
    std::vector<std::string> rowsOf;
    std::vector<std::ostringstream> blocks;
    std::string line;
    while (std::getline(file, line)) {
        if (line.empty()) {
            continue;
        }
        std::vector<std::string> fields = csvFields(line);
        if (fields.size() < 2) {
            continue;
        }
        const auto [found, inserted] = indexOf.emplace(fields[1], csv.bodies.size());
        if (inserted) {
            csv.bodies.push_back(fields[1]);
            blocks.emplace_back();
        }
        fields[1] = std::to_string(found->second);
        std::ostringstream& block = blocks[found->second];
        for (std::size_t i = 0; i < fields.size(); ++i) {
            block << (i == 0 ? "" : ",") << fields[i];
        }
        block << '\n';
    }
    if (csv.bodies.empty()) {
        throw scenario::ScenarioError({path.string(), 2}, "", "the CSV has no data rows");
    }
    for (const std::ostringstream& block : blocks) {
        csv.rows.push_back(block.str());
    }
    return csv;
}

std::string joined(const std::vector<std::string>& names)
{
    std::string text;
    for (std::size_t i = 0; i < names.size() && i < kMostCurves; ++i) {
        text += (i == 0 ? "" : ", ") + names[i];
    }
    return names.size() > kMostCurves ? text + ", ..." : text;
}

/// The indices of the bodies to draw: the one --body names, else every body (at most
/// kMostCurves).
std::vector<std::size_t> chosenBodies(const TumbleCsv& csv, const std::filesystem::path& path,
                                      const std::string& body)
{
    if (!body.empty()) {
        for (std::size_t i = 0; i < csv.bodies.size(); ++i) {
            if (csv.bodies[i] == body) {
                return {i};
            }
        }
        throw UsageError("--body", "no body named \"" + body + "\" in " + path.string() +
                                       " (bodies: " + joined(csv.bodies) + ")");
    }
    if (csv.bodies.size() > kMostCurves) {
        throw UsageError("--body", path.string() + " has " + std::to_string(csv.bodies.size()) +
                                       " bodies, too many curves for one plot; pick one with "
                                       "--body NAME (bodies: " +
                                       joined(csv.bodies) + ")");
    }
    std::vector<std::size_t> all(csv.bodies.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
        all[i] = i;
    }
    return all;
}

/// One plotted quantity: a gnuplot `using` expression, its title and style.
struct Curve {
    std::string expression;
    std::string title;
    std::string style;
};

/// The gnuplot script that plots the CSV at `path`; the image goes to standard output.
std::string scriptFor(const std::filesystem::path& path, const std::string& body)
{
    const TumbleCsv csv = readTumbleCsv(path);
    std::string kind;
    std::string ylabel;
    std::vector<Curve> curves;
    // with several bodies, one curve of the main quantity per body
    Curve perBody;
    if (csv.header.rfind("time,body,kinetic_linear", 0) == 0) {
        kind = "Energy ledger";
        ylabel = "energy (J)";
        curves = {{"6", "total", "lines lw 3"},
                  {"3", "kinetic (linear)", "lines"},
                  {"4", "kinetic (rotational)", "lines"},
                  {"5", "potential", "lines"},
                  {"7", "removed: normal impulses", "lines"},
                  {"8", "removed: friction", "lines"},
                  {"($9+$10+$11)", "removed: correction + integration + rest", "lines"},
                  {"12", "added by impulses", "lines"},
                  {"($6+$7+$8+$9+$10+$11-$12)", "total + removed - added (= initial)",
                   "lines dt 2 lw 2"}};
        perBody = {"6", "total energy", "lines lw 2"};
    } else if (csv.header.rfind("time,body,x,y,z", 0) == 0) {
        kind = "State";
        ylabel = "height (m), speed (m/s), spin (rad/s)";
        curves = {{"4", "height y", "lines lw 2"},
                  {"(sqrt($10**2+$11**2+$12**2))", "speed |v|", "lines lw 2"},
                  {"(sqrt($13**2+$14**2+$15**2))", "spin |w|", "lines lw 2"}};
        perBody = {"4", "height y", "lines lw 2"};
    } else if (csv.header.rfind("time,body,phase,vertex", 0) == 0) {
        kind = "Contact ledger";
        ylabel = "impulse (N s)";
        curves = {{"22", "normal", "points pt 7 ps 0.5"},
                  {"(sqrt($23**2+$24**2+$25**2))", "|friction|", "points pt 7 ps 0.5"}};
        perBody = {"22", "normal impulse", "points pt 7 ps 0.5"};
    } else {
        throw scenario::ScenarioError({path.string(), 1}, "",
                                      "not a CSV written by tumble run (unknown header)");
    }
    const std::vector<std::size_t> chosen = chosenBodies(csv, path, body);

    std::ostringstream script;
    script << "set terminal pngcairo size 1200,700 font 'sans,11'\n"
           << "set termoption noenhanced\n"
           << "set datafile separator ','\nset key below maxcols 3\nset grid\n"
           << "set xlabel 'time (s)'\nset ylabel " << quoted(ylabel) << "\n";
    // each body's rows as its own data block: a curve over rows interleaved with other bodies'
    // (NaN there) had no two neighbouring points and drew nothing
    for (const std::size_t i : chosen) {
        script << "$body" << i << " << EOD\n" << csv.rows[i] << "EOD\n";
    }
    const auto column = [](const std::string& expression) { return "1:" + expression; };
    if (chosen.size() == 1) {
        const std::size_t i = chosen.front();
        script << "set title " << quoted(kind + " of " + csv.bodies[i] + ": " +
                                         path.filename().string())
               << "\nplot ";
        for (std::size_t c = 0; c < curves.size(); ++c) {
            script << (c == 0 ? "" : ", ") << "$body" << i << " using "
                   << column(curves[c].expression) << " with " << curves[c].style << " title "
                   << quoted(curves[c].title);
        }
    } else {
        script << "set title " << quoted(kind + " of " + std::to_string(chosen.size()) +
                                         " bodies (" + perBody.title + "): " +
                                         path.filename().string())
               << "\nplot ";
        for (std::size_t c = 0; c < chosen.size(); ++c) {
            script << (c == 0 ? "" : ", ") << "$body" << chosen[c] << " using "
                   << column(perBody.expression) << " with " << perBody.style << " title "
                   << quoted(csv.bodies[chosen[c]]);
        }
    }
    script << "\n";
    return script.str();
}

/// The output folder, made if missing; exit code 3 when it cannot be.
void createDirectories(const std::string& directory)
{
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error) {
        throw OutputError("cannot write " + directory + ": " + error.message());
    }
}

/// Draws `script` with gnuplot into `png`, whole or not at all. The file is opened here first
/// (as PNG.tmp, renamed when gnuplot succeeds), so an output that cannot be written is exit 3
/// with the system's reason before gnuplot runs; gnuplot writes the image to its standard output,
/// which is that file, so no PNG data ever reaches the terminal.
void drawPng(const std::filesystem::path& png, const std::string& script)
{
    OutputFile image(png.string());
    runGnuplot(script, image.descriptor());
    image.finish();
    std::cout << "wrote " << png.string() << '\n';
}

/// The look of convergence series `i`: its own colour and point type. gnuplot's default cycle
/// repeats its colours after 8 series and the study has more; here a colour and a point type pair
/// repeats only after 16 x 15 series, and the first 15 differ in both.
std::string seriesStyle(std::size_t i)
{
    static constexpr std::array<const char*, 16> kColours{
        "#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f",
        "#bcbd22", "#17becf", "#000000", "#aec7e8", "#ffbb78", "#98df8a", "#ff9896", "#c5b0d5"};
    // pngcairo's 15 distinct point shapes
    constexpr std::size_t kPointTypes = 15;
    return std::string("lc rgb '") + kColours[i % kColours.size()] + "' pt " +
           std::to_string(1 + i % kPointTypes);
}

} // namespace

CLI::App* addPlotCommand(CLI::App& app, PlotOptions& options)
{
    CLI::App* command =
        app.add_subcommand("plot", "Plot CSV files written by tumble run to PNG (gnuplot)");
    command->add_option("CSV", options.files, "CSV files (--csv, --energy-csv, --contacts-csv)")
        ->required()
        ->type_name("");
    command->add_option("--out", options.outputDirectory, "Folder for the PNG files")
        ->type_name("DIR");
    command->add_option("--body", options.body,
                        "Plot only this body (default: every body, one curve each)")
        ->type_name("NAME");
    return command;
}

int plotCommand(const PlotOptions& options)
{
    for (const std::string& file : options.files) {
        const std::filesystem::path csv(file);
        std::filesystem::path png = csv;
        png.replace_extension(".png");
        if (!options.outputDirectory.empty()) {
            createDirectories(options.outputDirectory);
            png = std::filesystem::path(options.outputDirectory) / png.filename();
        }
        drawPng(png, scriptFor(csv, options.body));
    }
    return kExitOk;
}

void plotConvergence(const std::string& directory, const std::vector<Real>& steps,
                     const std::vector<ConvergenceSeries>& series)
{
    createDirectories(directory);
    const std::filesystem::path png = std::filesystem::path(directory) / "convergence.png";
    std::ostringstream script;
    script << "set terminal pngcairo size 1200,800 font 'sans,11'\n"
           << "set logscale xy\nset grid\nset key below maxcols 2\nset format y '1e%L'\n"
           << "set termoption noenhanced\nset xrange [*:0.02]\n"
           << "set xlabel 'dt (s)'\nset ylabel 'error'\n"
           << "set title 'tumble validate: error against time step'\n"
           << "plot ";
    for (std::size_t i = 0; i < series.size(); ++i) {
        script << (i == 0 ? "" : ", ") << "'-' using 1:2 with linespoints lw 2 "
               << seriesStyle(i) << " title " << quoted(series[i].label);
    }
    script << "\n";
    // errors at rounding level are drawn at the floor so log axes can show them
    for (const ConvergenceSeries& line : series) {
        for (std::size_t i = 0; i < steps.size() && i < line.errors.size(); ++i) {
            script << formatFull(steps[i]) << ' ' << formatFull(std::max(line.errors[i], 1e-16))
                   << '\n';
        }
        script << "e\n";
    }
    drawPng(png, script.str());
}

} // namespace tumble::cli
