#pragma once
// Lets the plain `apitrace trace bench ...` record an EGL run that eglretrace replays.
//
// `apitrace trace` preloads its GLX tracer (wrappers/glxtrace.so) unless told `--api egl`. That tracer
// wraps GL and GLX but no EGL function, so an EGL run traced through it loses its context creation and
// every function epoxy fetched through eglGetProcAddress (shaders, buffers, FBOs): the trace has draw
// calls with nothing to draw with and replays to nothing. Before the first EGL call of an EGL backend,
// a process that finds glxtrace.so in LD_PRELOAD with apitrace's EGL tracer (egltrace.so) beside it
// restarts itself, same arguments and environment, with egltrace.so preloaded instead: what
// `apitrace trace --api egl` would have done. The trace file apitrace chose (TRACE_FILE, or the
// process name) stays the same, and nothing has been written to it yet (the tracer opens it at its
// first traced call).
#include <string>

namespace sb {

class ApitraceHandoff {
public:
    /// Re-executes the process under egltrace.so when the GLX tracer is preloaded and loaded, with
    /// egltrace.so beside it; returns otherwise
    /// (also when re-executing fails, after saying why on stderr: the run then goes on untraced-EGL).
    static void toEglTracer();
    /// LD_PRELOAD with each ".../glxtrace.so" entry replaced by ".../egltrace.so" in the same directory
    /// (text only, ld.so tokens such as $LIB kept), or "" when `preload` names no glxtrace.so (tests).
    static std::string eglPreload(const std::string& preload);
};

} // namespace sb
