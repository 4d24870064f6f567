#pragma once
// One exception type for every user-facing error. The message is the one line printed before a
// non-zero exit, so it must name what was wrong and where (file, JSON path, option, GL pass ...).
#include <stdexcept>
#include <string>

namespace sb {

/// Exit codes of the bench binary (docs/ARCHITECTURE.md, "Errors and exit codes"). Tests check them.
enum class ExitCode : int {
    Ok = 0,
    Failure = 1,     ///< a run failed (GL error, I/O error while running)
    BadInput = 2,    ///< bad command line, scene file, property, model file
    Unsupported = 3, ///< the GL context lacks a capability the technique needs
};

/// The exit code of a run that met several: a failed run (1) over bad input (2) over what the context
/// lacks (3) over success (0), so the most serious cause is the one the caller sees.
constexpr ExitCode worseExitCode(ExitCode a, ExitCode b) {
    auto rank = [](ExitCode c) {
        return c == ExitCode::Failure ? 3 : c == ExitCode::BadInput ? 2 : c == ExitCode::Unsupported ? 1 : 0;
    };
    return rank(b) > rank(a) ? b : a;
}

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message, ExitCode code = ExitCode::BadInput)
        : std::runtime_error(message), mCode(code) {}
    ExitCode code() const { return mCode; }

private:
    ExitCode mCode;
};

} // namespace sb
