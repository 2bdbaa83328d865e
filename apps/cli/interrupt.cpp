#include "interrupt.hpp"

#include <csignal>

namespace tumble::cli {
namespace {

volatile std::sig_atomic_t g_received = 0;

struct sigaction g_previousInt {};
struct sigaction g_previousTerm {};

extern "C" void recordSignal(int signal) { g_received = signal; }

} // namespace

InterruptGuard::InterruptGuard()
{
    g_received = 0;
    struct sigaction action {};
    action.sa_handler = recordSignal;
    sigemptyset(&action.sa_mask);
    // One signal stops the run at the next step; a second one ends the process at once.
    action.sa_flags = SA_RESETHAND;
    sigaction(SIGINT, &action, &g_previousInt);
    sigaction(SIGTERM, &action, &g_previousTerm);
}

InterruptGuard::~InterruptGuard()
{
    sigaction(SIGINT, &g_previousInt, nullptr);
    sigaction(SIGTERM, &g_previousTerm, nullptr);
}

int InterruptGuard::received() { return g_received; }

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
