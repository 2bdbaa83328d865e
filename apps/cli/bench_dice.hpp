// The throughput rows of `tumble bench`: whole throws as `tumble throw` runs them (docs/dice.md).
#pragma once

#include "tumble/scenario/scenario.hpp"

namespace tumble::cli {

/// Times `throws` throws of the single die (seed 1) on `threads` threads and prints one row.
void printDiceRow(const scenario::Scenario& die, long throws, int threads);

/// The same for a scenario of several dice (dice_two_in_tray): a throw ends when every die rests.
void printTrayRow(const scenario::Scenario& tray, long throws, int threads);

} // namespace tumble::cli
