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

std::int64_t runThrows(const scenario::Scenario& scenario, std::uint64_t seed,
                       std::int64_t firstIndex, std::span<scenario::ThrowOutcome> outcomes,
                       std::span<std::uint8_t> finished, int threads, bool progress,
                       std::int64_t totalThrows)
{
    ProgressBar bar(static_cast<std::int64_t>(outcomes.size()), totalThrows, "throws");
    scenario::ThrowBatchHooks hooks;
    // a signal skips the throws not yet started
    hooks.stopRequested = [] { return InterruptGuard::received() != 0; };
    if (progress) {
        hooks.progress = [&bar](std::int64_t done) { bar.update(done); };
    }
    const std::int64_t done =
        scenario::runThrowBatch(scenario, seed, firstIndex, outcomes, finished, threads, hooks);
    if (progress) {
        bar.update(done, true);
        ProgressBar::clear();
    }
    return done;
}

} // namespace tumble::cli
