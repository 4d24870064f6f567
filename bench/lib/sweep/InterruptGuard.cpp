#include "bench/lib/sweep/InterruptGuard.h"

#include "bench/lib/sweep/ChildProcess.h"

namespace sb {

namespace {

volatile std::sig_atomic_t gInterrupted = 0;

void onInterrupt(int sig) {
    gInterrupted = 1;
    ChildProcess::interruptCurrent(sig);
}

} // namespace

InterruptGuard::InterruptGuard() {
    gInterrupted = 0;
    struct sigaction sa {};
    sa.sa_handler = onInterrupt;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, &mOldInt);
    sigaction(SIGTERM, &sa, &mOldTerm);
}

InterruptGuard::~InterruptGuard() {
    sigaction(SIGINT, &mOldInt, nullptr);
    sigaction(SIGTERM, &mOldTerm, nullptr);
}

const volatile std::sig_atomic_t& InterruptGuard::flag() {
    return gInterrupted;
}

} // namespace sb
