// Stopping a run cleanly on SIGINT or SIGTERM: the handler only records the signal; the run loop
// asks for it between steps, stops, and writes complete output up to that time.
#pragma once

namespace tumble::cli {

/// While alive, SIGINT and SIGTERM are recorded instead of ending the process; a second signal
/// ends it as usual (the handlers reset themselves). The previous handlers come back at
/// destruction.
class InterruptGuard {
public:
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    /// The signal received (SIGINT or SIGTERM), or 0.
    [[nodiscard]] static int received();
};

/// "SIGINT", "SIGTERM" or "signal N".
const char* signalName(int signal);

} // namespace tumble::cli
