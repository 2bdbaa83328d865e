#include "plot_command.hpp"

#include "console.hpp"

#include "tumble/scenario/scenario.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace tumble::cli {
namespace {

/// Runs gnuplot on a script; gnuplot is a Debian package (gnuplot-nox) that tools/install-deps.sh
/// installs.
void runGnuplot(const std::string& script, const std::filesystem::path& scriptPath)
{
    {
        std::ofstream file(scriptPath);
        file << script;
        if (!file) {
            throw std::runtime_error("cannot write " + scriptPath.string());
        }
    }
    const std::string command = "gnuplot '" + scriptPath.string() + "'";
    const int status = std::system(command.c_str());
    std::filesystem::remove(scriptPath);
    if (status != 0) {
        throw std::runtime_error("gnuplot failed (is gnuplot installed? tools/install-deps.sh "
                                 "installs gnuplot-nox)");
    }
}

std::string quoted(const std::string& text)
{
    std::string escaped;
    for (const char c : text) {
        escaped += (c == '\'' ? std::string("''") : std::string(1, c));
    }
    return "'" + escaped + "'";
}

std::string firstLine(const std::filesystem::path& path)
{
    std::ifstream file(path);
    std::string line;
    if (!file || !std::getline(file, line)) {
        throw scenario::ScenarioError({path.string(), 0}, "", "cannot read a CSV header");
    }
    return line;
}

/// The body named in the first data row: multi-body files are plotted for that body.
std::string firstBody(const std::filesystem::path& path)
{
    std::ifstream file(path);
    std::string line;
    std::getline(file, line);
    if (!std::getline(file, line)) {
        throw scenario::ScenarioError({path.string(), 2}, "", "the CSV has no data rows");
    }
    const std::size_t start = line.find(',') + 1;
    return line.substr(start, line.find(',', start) - start);
}

std::string scriptFor(const std::filesystem::path& csv, const std::filesystem::path& png)
{
    const std::string header = firstLine(csv);
    std::ostringstream script;
    script << "set terminal pngcairo size 1200,700 font 'sans,11'\n"
           << "set output " << quoted(png.string()) << "\n"
           << "set termoption noenhanced\n"
           << "set datafile separator ','\nset key below maxcols 3\nset grid\n"
           << "set xlabel 'time (s)'\n";
    const std::string data = csv.string();
    const std::string body = firstBody(csv);
    // Column c of the first body's rows only (NaN elsewhere, which gnuplot skips).
    const auto of = [&](const std::string& expression) {
        return "(strcol(2) eq " + quoted(body) + " ? " + expression + " : NaN)";
    };
    if (header.rfind("time,body,kinetic_linear", 0) == 0) {
        script << "set title 'Energy ledger of " << body << ": " << csv.filename().string()
               << "'\n"
               << "set ylabel 'energy (J)'\n"
               << "plot " << quoted(data) << " using 1:" << of("$6") << " with lines lw 3 title 'total',"
               << quoted(data) << " using 1:" << of("$3") << " with lines title 'kinetic (linear)',"
               << quoted(data) << " using 1:" << of("$4") << " with lines title 'kinetic (rotational)',"
               << quoted(data) << " using 1:" << of("$5") << " with lines title 'potential',"
               << quoted(data) << " using 1:" << of("$7") << " with lines title 'removed: normal impulses',"
               << quoted(data) << " using 1:" << of("$8") << " with lines title 'removed: friction',"
               << quoted(data) << " using 1:" << of("($9+$10+$11)")
               << " with lines title 'removed: correction + integration + rest',"
               << quoted(data) << " using 1:" << of("$12") << " with lines title 'added by impulses',"
               << quoted(data) << " using 1:" << of("($6+$7+$8+$9+$10+$11-$12)")
               << " with lines dt 2 lw 2 title 'total + removed - added (= initial)'\n";
    } else if (header.rfind("time,body,x,y,z", 0) == 0) {
        script << "set title 'State of " << body << ": " << csv.filename().string() << "'\n"
               << "set ylabel 'height (m), speed (m/s), spin (rad/s)'\n"
               << "plot " << quoted(data) << " using 1:" << of("$4") << " with lines lw 2 title 'height y', "
               << quoted(data) << " using 1:" << of("sqrt($10**2+$11**2+$12**2)")
               << " with lines lw 2 title 'speed |v|', " << quoted(data) << " using 1:"
               << of("sqrt($13**2+$14**2+$15**2)") << " with lines lw 2 title 'spin |w|'\n";
    } else if (header.rfind("time,body,phase,vertex", 0) == 0) {
        script << "set title 'Contact ledger: " << csv.filename().string() << "'\n"
               << "set ylabel 'impulse (N s)'\n"
               << "plot " << quoted(data) << " using 1:" << of("$22")
               << " with points pt 7 ps 0.5 title 'normal', " << quoted(data) << " using 1:"
               << of("sqrt($23**2+$24**2+$25**2)") << " with points pt 7 ps 0.5 title '|friction|'\n";
    } else {
        throw scenario::ScenarioError({csv.string(), 1}, "",
                                      "not a CSV written by tumble run (unknown header)");
    }
    return script.str();
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
    return command;
}

int plotCommand(const PlotOptions& options)
{
    for (const std::string& file : options.files) {
        const std::filesystem::path csv(file);
        std::filesystem::path png = csv;
        png.replace_extension(".png");
        if (!options.outputDirectory.empty()) {
            std::filesystem::create_directories(options.outputDirectory);
            png = std::filesystem::path(options.outputDirectory) / png.filename();
        }
        runGnuplot(scriptFor(csv, png), png.string() + ".gp");
        std::cout << "wrote " << png.string() << '\n';
    }
    return kExitOk;
}

void plotConvergence(const std::string& directory, const std::vector<Real>& steps,
                     const std::vector<ConvergenceSeries>& series)
{
    std::filesystem::create_directories(directory);
    const std::filesystem::path png = std::filesystem::path(directory) / "convergence.png";
    std::ostringstream script;
    script << "set terminal pngcairo size 1200,800 font 'sans,11'\n"
           << "set output " << quoted(png.string()) << "\n"
           << "set logscale xy\nset grid\nset key below maxcols 2\nset format y '1e%L'\n"
           << "set termoption noenhanced\nset xrange [*:0.02]\n"
           << "set xlabel 'dt (s)'\nset ylabel 'error'\n"
           << "set title 'tumble validate: error against time step'\n"
           << "plot ";
    bool first = true;
    for (const ConvergenceSeries& line : series) {
        // Errors at rounding level are drawn at the floor so log axes can show them.
        script << (first ? "" : ", ") << "'-' using 1:2 with linespoints lw 2 title "
               << quoted(line.label);
        first = false;
    }
    script << "\n";
    for (const ConvergenceSeries& line : series) {
        for (std::size_t i = 0; i < steps.size() && i < line.errors.size(); ++i) {
            script << formatFull(steps[i]) << ' ' << formatFull(std::max(line.errors[i], 1e-16))
                   << '\n';
        }
        script << "e\n";
    }
    runGnuplot(script.str(), png.string() + ".gp");
    std::cout << "wrote " << png.string() << '\n';
}

} // namespace tumble::cli
