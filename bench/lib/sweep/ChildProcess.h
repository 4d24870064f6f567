#pragma once
// Runs one worker process of a sweep and reports how it ended. A worker per group isolates
// what a configuration can do to the ones after it: a crash (SIGSEGV in a driver), a GL error that
// leaves the context in an unknown state, leaked GL objects, an environment variable such as
// LP_NO_RAST=1 that must apply to one configuration only.
//
// The child's stdout is read line by line (the worker's progress protocol), its stderr kept as a tail
// for the failure message. The child dies with the parent (PR_SET_PDEATHSIG), so a killed sweep leaves
// no orphan measuring in the background. interruptCurrent() is async-signal-safe: the sweep's SIGINT
// handler forwards the signal with it.
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace sb {

struct ChildExit {
    int exitCode = -1;      ///< valid when signal == 0
    int signal = 0;         ///< the signal that killed it, 0 when it exited
    std::string stderrTail; ///< the last lines the child wrote to stderr
    /// "exit code 2" or "killed by signal 11 (Segmentation fault)".
    std::string describe() const;
    bool ok() const { return signal == 0 && exitCode == 0; }
};

class ChildProcess {
public:
    using LineHandler = std::function<void(const std::string&)>;
    /// Runs `argv` (argv[0] is the executable path) with the parent's environment plus `env`, calls
    /// `onStdoutLine` for every line of its stdout, and waits for it. Throws sb::Error(Failure) when the
    /// process cannot be started.
    static ChildExit run(const std::vector<std::string>& argv,
                         const std::vector<std::pair<std::string, std::string>>& env,
                         const LineHandler& onStdoutLine);
    /// Sends `sig` to the child being run, if any (async-signal-safe).
    static void interruptCurrent(int sig);
    /// The running executable (/proc/self/exe), to start workers of the same build.
    static std::string selfExecutable();
};

} // namespace sb
