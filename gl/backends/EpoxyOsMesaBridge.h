#pragma once
// Makes libepoxy's GL entry points work while an OSMesa context is current.
//
// libepoxy only knows GLX and EGL: with an OSMesa context current, GL 1.x functions resolve to
// libglvnd's libGL.so.1 (which has no current context and returns nothing) and every later function
// aborts inside epoxy_get_proc_address ("Couldn't find current GLX or EGL context"). epoxy's public
// function pointers (epoxy_glBegin, epoxy_glGenFramebuffers ...) are plain writable globals, so the
// bridge points each of them at OSMesaGetProcAddress's answer while OSMesa is current, and puts the
// previous values back before another backend's context is used.
#include <cstddef>

namespace sb {

class EpoxyOsMesaBridge {
public:
    /// Points epoxy's GL function pointers at libOSMesa's (an OSMesa context must be current).
    /// Idempotent. Throws sb::Error when epoxy's symbol table cannot be read.
    static void install();
    /// Restores the pointers saved by install(); no-op when not installed.
    static void restore();
    static bool installed();
    /// Number of epoxy GL pointers redirected by the last install() (diagnostics, tests).
    static size_t redirectedCount();
};

} // namespace sb
