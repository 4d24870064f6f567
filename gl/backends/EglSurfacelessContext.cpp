#include "gl/backends/EglSurfacelessContext.h"

#include "core/Error.h"
#include "gl/backends/ApitraceHandoff.h"

namespace sb {

EglSurfacelessContext::EglSurfacelessContext(const ContextOptions& options)
    : EglContext(openDisplay(), options, "egl-surfaceless") {}

EGLDisplay EglSurfacelessContext::openDisplay() {
    // Before the first EGL call: a GLX tracer would record none of them.
    ApitraceHandoff::toEglTracer();
    // Client extensions are queried on EGL_NO_DISPLAY; a missing platform is a clear reason, not a crash.
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless"))
        throw Error("egl-surfaceless: EGL client extension EGL_MESA_platform_surfaceless missing",
                    ExitCode::Unsupported);
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_base"))
        throw Error("egl-surfaceless: EGL_EXT_platform_base missing", ExitCode::Unsupported);
    return eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
}

} // namespace sb
