// CsvWriter: the per-body state samples of `tumble run --csv`, written to a file (through a
// temporary file renamed on completion, so a failed run leaves no half file) or to stdout.
#pragma once

#include "output_file.hpp"

#include "tumble/scenario/runner.hpp"

#include <string>

namespace tumble::cli {

class CsvWriter {
public:
    /// "-" means stdout; any other path is written as PATH.tmp and renamed by finish().
    explicit CsvWriter(const std::string& path);

    /// One row per body: time, name, position, orientation (w, x, y, z), velocity, angular
    /// velocity, kinetic and potential energy, every number as %.17g.
    void writeSample(const scenario::Runner& runner);
    /// Flushes, closes and renames the temporary file into place. Throws on a write error.
    void finish() { m_output.finish(); }

private:
    OutputFile m_output;
};

} // namespace tumble::cli
