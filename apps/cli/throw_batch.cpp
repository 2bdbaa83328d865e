// `tumble throw`'s batches: the library's runThrowBatch with the CLI's signals and progress bar.
#include "throw_batch.hpp"

#include "cli_options.hpp"
#include "interrupt.hpp"
#include "progress_bar.hpp"

#include "tumble/scenario/throw_batch.hpp"

#include <algorithm>

namespace tumble::cli {

int defaultThreadCount() { return std::clamp(scenario::throwCoreCount(), 1, kMaxThreads); }

bool parallelBuild() { return scenario::parallelThrowBuild(); }

namespace {

/// Runs `batch(hooks)` with the CLI's signal handling and, with `progress`, its progress bar.
template <typename Batch>
std::int64_t withHooks(std::int64_t throws, bool progress, std::int64_t totalThrows,
                       const Batch& batch)
{
    ProgressBar bar(throws, totalThrows, "throws");
    scenario::ThrowBatchHooks hooks;
    // a signal skips the throws not yet started
    hooks.stopRequested = [] { return InterruptGuard::received() != 0; };
    if (progress) {
        hooks.progress = [&bar](std::int64_t done) { bar.update(done); };
    }
    const std::int64_t done = batch(hooks);
    if (progress) {
        bar.update(done, true);
        ProgressBar::clear();
    }
    return done;
}

} // namespace

std::int64_t runThrows(const scenario::Scenario& scenario, std::uint64_t seed,
                       std::int64_t firstIndex, std::span<scenario::ThrowOutcome> outcomes,
                       std::span<std::uint8_t> finished, int threads, bool progress,
                       std::int64_t totalThrows)
{
    return withHooks(static_cast<std::int64_t>(outcomes.size()), progress, totalThrows,
                     [&](const scenario::ThrowBatchHooks& hooks) {
                         return scenario::runThrowBatch(scenario, seed, firstIndex, outcomes,
                                                        finished, threads, hooks);
                     });
}

std::int64_t runDiceThrows(const scenario::Scenario& scenario, std::uint64_t seed,
                           std::int64_t firstIndex, std::span<scenario::DieOutcome> outcomes,
                           std::span<std::uint8_t> finished, int threads, bool progress,
                           std::int64_t totalThrows)
{
    return withHooks(static_cast<std::int64_t>(finished.size()), progress, totalThrows,
                     [&](const scenario::ThrowBatchHooks& hooks) {
                         return scenario::runDiceBatch(scenario, seed, firstIndex, outcomes,
                                                       finished, threads, hooks);
                     });
}

} // namespace tumble::cli
