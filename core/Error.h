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

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message, ExitCode code = ExitCode::BadInput)
        : std::runtime_error(message), mCode(code) {}
    ExitCode code() const { return mCode; }

private:
    ExitCode mCode;
};

} // namespace sb
