// Stopping a run cleanly on SIGINT or SIGTERM: the handler only records the signal; the run loop
// asks for it between steps, stops, and writes complete output up to that time.
#pragma once

#include <string>

namespace tumble::cli {

/// While alive, SIGINT and SIGTERM are recorded instead of ending the process. Signals within
/// 0.25 s of the first are the same request (GNU timeout sends two at once); a later one ends the
/// process at once, by the signal, after removing the registered temporary files. The previous
/// handlers come back at destruction.
class InterruptGuard {
public:
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    /// The signal received (SIGINT or SIGTERM), or 0.
    [[nodiscard]] static int received();
};

/// Registers a temporary file for removal if a second signal ends the process at once; returns
/// the slot to unregister, or -1 when none is free (the file may then stay behind).
int registerTemporaryFile(const std::string& path);
void unregisterTemporaryFile(int slot);

/// "SIGINT", "SIGTERM" or "signal N".
const char* signalName(int signal);

} // namespace tumble::cli
