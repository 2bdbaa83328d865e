// `tumble throw` for a scenario of several dice (or one die among static geometry): the throws,
// the report of dice_report.hpp, and --replay of every die of one throw.
#pragma once

#include "mpi_session.hpp"
#include "throw_command.hpp"

#include "tumble/scenario/scenario.hpp"

namespace tumble::cli {

/// Whether the scenario is thrown by the single-die model of today's files: one [[body]], a
/// ground, no region and no cluster. Such files keep their output byte for byte.
bool singleDieThrow(const scenario::Scenario& scenario);

/// Fails with a ScenarioError on `throw.region` when a die of the first throws cannot be placed
/// clear of the others and of static geometry.
void checkDicePlacement(const ThrowOptions& options, const scenario::Scenario& loaded);

/// Runs the throws and reports them; returns the exit code.
int throwDiceCommand(const ThrowOptions& options, const scenario::Scenario& loaded,
                     const MpiSession& mpi);

/// --replay I --out PATH: every die of throw I as a scenario file, and what they give.
int writeDiceReplay(const ThrowOptions& options, const scenario::Scenario& loaded);

} // namespace tumble::cli
