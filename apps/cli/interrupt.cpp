#include "interrupt.hpp"

#include <time.h>
#include <unistd.h>

#include <csignal>
#include <cstring>

namespace tumble::cli {
namespace {

/// Signals closer than this to the first one are the same request: GNU timeout signals the child
/// and then its process group, so one `timeout` delivers SIGTERM twice within microseconds.
constexpr long kSameRequestNanoseconds = 250'000'000;

/// Temporary files an immediate end removes; fixed storage, as the handler may not allocate.
constexpr int kTemporarySlots = 16;
constexpr std::size_t kPathCapacity = 4096;

volatile std::sig_atomic_t g_received = 0;
/// CLOCK_MONOTONIC time of the first signal, ns.
volatile long long g_firstSignalNs = 0;

struct TemporarySlot {
    volatile std::sig_atomic_t used = 0;
    char path[kPathCapacity] = {};
};
TemporarySlot g_temporaries[kTemporarySlots];

struct sigaction g_previousInt {};
struct sigaction g_previousTerm {};

long long monotonicNs()
{
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    return static_cast<long long>(now.tv_sec) * 1'000'000'000LL + now.tv_nsec;
}

/// Only async-signal-safe calls: clock_gettime, unlink, signal, raise.
extern "C" void recordSignal(int signal)
{
    const long long now = monotonicNs();
    if (g_received == 0) {
        g_received = signal;
        g_firstSignalNs = now;
        return;
    }
    if (now - g_firstSignalNs < kSameRequestNanoseconds) {
        return;
    }
    // a second request ends the process at once; no half-written temporary file stays behind
    for (TemporarySlot& slot : g_temporaries) {
        if (slot.used != 0) {
            unlink(slot.path);
        }
    }
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

} // namespace

InterruptGuard::InterruptGuard()
{
    g_received = 0;
    struct sigaction action {};
    action.sa_handler = recordSignal;
    sigemptyset(&action.sa_mask);
    // both signals are blocked while the handler runs, so it never interrupts itself
    sigaddset(&action.sa_mask, SIGINT);
    sigaddset(&action.sa_mask, SIGTERM);
    action.sa_flags = 0;
    sigaction(SIGINT, &action, &g_previousInt);
    sigaction(SIGTERM, &action, &g_previousTerm);
}

InterruptGuard::~InterruptGuard()
{
    sigaction(SIGINT, &g_previousInt, nullptr);
    sigaction(SIGTERM, &g_previousTerm, nullptr);
}

int InterruptGuard::received() { return g_received; }

int registerTemporaryFile(const std::string& path)
{
    if (path.size() >= kPathCapacity) {
        return -1;
    }
    for (int i = 0; i < kTemporarySlots; ++i) {
        TemporarySlot& slot = g_temporaries[i];
        if (slot.used == 0) {
            std::memcpy(slot.path, path.c_str(), path.size() + 1);
            slot.used = 1;
            return i;
        }
    }
    return -1;
}

void unregisterTemporaryFile(int slot)
{
    if (slot >= 0 && slot < kTemporarySlots) {
        g_temporaries[slot].used = 0;
    }
}

const char* signalName(int signal)
{
    switch (signal) {
    case SIGINT:
        return "SIGINT";
    case SIGTERM:
        return "SIGTERM";
    default:
        return "a signal";
    }
}

} // namespace tumble::cli
