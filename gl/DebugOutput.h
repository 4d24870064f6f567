#pragma once
// KHR_debug: a GL error fails the run with the driver's message and the pass it happened in.
// The callback only records (throwing through the driver is undefined behaviour); the harness calls
// check() after each pass and at the end of the frame, which throws sb::Error(ExitCode::Failure):
//   "GL error in pass 'shadowmap/depth': GL_INVALID_OPERATION: <driver message>"
#include <string>
#include <vector>

namespace sb {

class DebugOutput {
public:
    /// Installs the callback (synchronous output) on the current context. Returns false when the
    /// context has no KHR_debug (then check() falls back to glGetError).
    static bool install();
    /// Name of the pass now running, reported with errors ("" outside passes).
    static void setCurrentPass(const std::string& name);
    static const std::string& currentPass();
    /// Throws if an error was recorded (or glGetError reports one) since the last check.
    static void check();
    /// Performance/other warnings seen (not errors), for --verbose.
    static std::vector<std::string> takeWarnings();
};

} // namespace sb
