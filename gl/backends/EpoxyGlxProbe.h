#pragma once
// Keeps libepoxy's "is a GLX context current?" probe from aborting under a GL tracer.
//
// Before it resolves a GL function, libepoxy asks whether the current context is GLX: once it has
// dlopen()ed "libGL.so.1" (which it does for every desktop-GL context, EGL ones included, to find the
// GL 1.x symbols) it calls glXGetCurrentContext through its own GLX dispatch, which looks the symbol up
// in that handle and aborts when it is missing ("glXGetCurrentContext() not found"). Under apitrace's
// EGL tracer (`apitrace trace --api egl`) the dlopen is redirected to egltrace.so, which exports GL and
// EGL but no GLX symbol, so the first GL call of an EGL run aborted (libepoxy's dispatch_common.c,
// epoxy_get_bootstrap_proc_address; reported upstream as libepoxy issue "undefined
// glXGetCurrentContext on EGL tracing").
//
// epoxy_glXGetCurrentContext is one of epoxy's public, writable function-pointer globals (the same
// mechanism EpoxyOsMesaBridge uses), so while an EGL context of ours exists it points at a probe that
// forwards to a glXGetCurrentContext some loaded library really exports (libGL.so.1, apitrace's GLX
// tracer) and answers "no GLX context" when none does, which is the truth for a process whose context
// is EGL. epoxy then takes its EGL path: GL 1.x symbols from its libGL handle, the rest through
// eglGetProcAddress, both of which the tracer wraps.
namespace sb {

/// Held by each EGL context (a member, so it is in place before the first GL call and also released
/// when the context's constructor throws). Reference counted across contexts.
class EpoxyGlxProbe {
public:
    /// Points epoxy_glXGetCurrentContext at the probe (the first holder does).
    EpoxyGlxProbe();
    /// The last holder puts epoxy's own pointer back.
    ~EpoxyGlxProbe();
    EpoxyGlxProbe(const EpoxyGlxProbe&) = delete;
    EpoxyGlxProbe& operator=(const EpoxyGlxProbe&) = delete;
    /// Whether some holder is alive (tests).
    static bool installed();
};

} // namespace sb
