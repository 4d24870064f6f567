#pragma once
// Shared part of the EGL backends (EglSurfacelessContext, EglDeviceContext): given an EGLDisplay from
// some platform, initialises it, binds desktop OpenGL and creates a 4.5 compatibility-profile context
// made current without a surface (EGL_KHR_surfaceless_context).
#include <string>

#include <epoxy/egl.h>

#include "gl/Context.h"
#include "gl/backends/EpoxyGlxProbe.h"

namespace sb {

class EglContext : public Context {
public:
    ~EglContext() override;
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;
    void makeCurrent() override;
    EGLDisplay display() const { return mDisplay; }

    /// "EGL_BAD_MATCH" etc. for messages.
    static std::string eglErrorName(EGLint error);

protected:
    /// `what` prefixes every failure message ("egl-surfaceless", "egl-device 0"). Throws sb::Error.
    EglContext(EGLDisplay display, const ContextOptions& options, const std::string& what);

private:
    void initializeDisplay();
    EGLConfig chooseConfig() const;
    void createGlContext(const ContextOptions& options);
    [[noreturn]] void fail(const std::string& reason) const;

    /// First member: in place before the first GL call, so epoxy's GLX probe cannot abort under
    /// apitrace's EGL tracer (see EpoxyGlxProbe.h).
    EpoxyGlxProbe mGlxProbe;
    EGLDisplay mDisplay = EGL_NO_DISPLAY;
    EGLContext mContext = EGL_NO_CONTEXT;
    std::string mWhat;
};

} // namespace sb
