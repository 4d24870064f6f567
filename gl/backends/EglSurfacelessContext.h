#pragma once
// egl-surfaceless: Mesa's EGL_MESA_platform_surfaceless display (no window system, no device choice).
// On Mesa without a GPU this is llvmpipe; the default headless backend.
#include "gl/backends/EglContext.h"

namespace sb {

class EglSurfacelessContext : public EglContext {
public:
    /// Throws sb::Error("egl-surfaceless: <reason>", ExitCode::Unsupported) when the platform is missing
    /// or no 4.5 compatibility context can be created.
    explicit EglSurfacelessContext(const ContextOptions& options);
    Backend backend() const override { return Backend::EglSurfaceless; }

private:
    static EGLDisplay openDisplay();
};

} // namespace sb
