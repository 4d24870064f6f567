#pragma once
// Why a program run under valgrind did not finish, in one line, from its wait status and valgrind's log
// (the child's stderr, where valgrind and the program both write).
//
// The case it exists for: valgrind's CPU (VEX) does not know every instruction the host runs. A library
// that executes one (Debian 12's libhwy runs RDTSCP when it is loaded, on CPUs whose CPUID hides the
// instruction: valgrind then refuses it) is killed by SIGILL before main, and the log's last line
// ("I refs: 0") says nothing of it. That is the machine lacking what layer B needs (exit 3), not a
// failed gate (exit 1).
//
//     ValgrindDiagnosis d = ValgrindDiagnosis::of(status, readFile("ci-out/callgrind/x/stderr.txt"));
//     d.unsupported; // true: valgrind could not run the program here
//     d.reason;      // "killed by SIGILL: valgrind cannot execute the instruction at 0x159EF522 (bytes
//                    //  0F 01 F9, RDTSCP) in hwy::platform::TimerResolution() (libhwy.so.1.0.3), while
//                    //  a shared library was being loaded"
#include <string>

namespace sb {

struct ValgrindDiagnosis {
    bool unsupported = false; ///< valgrind itself could not run the program (exit 3), not the program failing
    std::string reason;       ///< one line, without the log's path (the caller adds where it is)

    /// `waitStatus` as waitpid gives it; `log` the child's whole stderr.
    static ValgrindDiagnosis of(int waitStatus, const std::string& log);
    /// The instruction's name for the first bytes VEX printed ("0xF 0x1 0xF9 ..."), "" when unknown.
    static std::string instructionName(const std::string& bytes);
};

} // namespace sb
