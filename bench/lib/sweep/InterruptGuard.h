#pragma once
// SIGINT and SIGTERM turned into a flag for the lifetime of a long command (a sweep, a bisection), so
// that it stops between steps and unwinds: rows already written stay, temporary worktrees and files are
// removed. The signal is also passed to the child process running at that moment (ChildProcess), since a
// kill of the parent alone must stop its worker too. The previous handlers come back at destruction.
#include <csignal>

namespace sb {

class InterruptGuard {
public:
    /// Clears the flag and installs the handlers.
    InterruptGuard();
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

    /// Set once SIGINT or SIGTERM arrived while a guard was alive.
    static const volatile std::sig_atomic_t& flag();
    static bool interrupted() { return flag() != 0; }

private:
    struct sigaction mOldInt {
    }, mOldTerm{};
};

} // namespace sb
