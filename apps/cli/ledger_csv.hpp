// The ledgers of `tumble run`: --energy-csv (where each body's energy went, every step) and
// --contacts-csv (every contact point of every solve), both written whole or not at all.
#pragma once

#include "output_file.hpp"

#include "tumble/scenario/runner.hpp"

#include <string>

namespace tumble::cli {

/// One row per body per step: kinetic (linear, rotational), potential, total, each ledger
/// heading, and the balance error total + removed - added - initial.
class EnergyCsv {
public:
    explicit EnergyCsv(const std::string& path);
    void writeStep(const scenario::Runner& runner);
    void finish() { m_output.finish(); }

private:
    OutputFile m_output;
};

/// One row per contact point of every contact solve of a step (the world must record contacts).
class ContactsCsv {
public:
    explicit ContactsCsv(const std::string& path);
    void writeStep(const scenario::Runner& runner);
    void finish() { m_output.finish(); }

private:
    OutputFile m_output;
};

} // namespace tumble::cli
