#include "gl/backends/EglContext.h"

#include <cstdio>

#include "core/Error.h"
#include "core/NameTable.h"
#include "gl/backends/EpoxyOsMesaBridge.h"

namespace sb {

namespace {
constexpr Named<EGLint> kEglErrorNames[] = {
    {EGL_SUCCESS, "EGL_SUCCESS"},
    {EGL_NOT_INITIALIZED, "EGL_NOT_INITIALIZED"},
    {EGL_BAD_ACCESS, "EGL_BAD_ACCESS"},
    {EGL_BAD_ALLOC, "EGL_BAD_ALLOC"},
    {EGL_BAD_ATTRIBUTE, "EGL_BAD_ATTRIBUTE"},
    {EGL_BAD_CONFIG, "EGL_BAD_CONFIG"},
    {EGL_BAD_CONTEXT, "EGL_BAD_CONTEXT"},
    {EGL_BAD_CURRENT_SURFACE, "EGL_BAD_CURRENT_SURFACE"},
    {EGL_BAD_DISPLAY, "EGL_BAD_DISPLAY"},
    {EGL_BAD_MATCH, "EGL_BAD_MATCH"},
    {EGL_BAD_NATIVE_PIXMAP, "EGL_BAD_NATIVE_PIXMAP"},
    {EGL_BAD_NATIVE_WINDOW, "EGL_BAD_NATIVE_WINDOW"},
    {EGL_BAD_PARAMETER, "EGL_BAD_PARAMETER"},
    {EGL_BAD_SURFACE, "EGL_BAD_SURFACE"},
    {EGL_CONTEXT_LOST, "EGL_CONTEXT_LOST"},
};
constexpr NameTable kEglErrors{kEglErrorNames};
} // namespace

EglContext::EglContext(EGLDisplay display, const ContextOptions& options, const std::string& what)
    : mDisplay(display), mWhat(what) {
    if (mDisplay == EGL_NO_DISPLAY) fail("no EGL display (" + eglErrorName(eglGetError()) + ")");
    initializeDisplay();
    createGlContext(options);
    makeCurrent();
}

EglContext::~EglContext() {
    if (mContext == EGL_NO_CONTEXT) return;
    if (eglGetCurrentContext() == mContext)
        eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(mDisplay, mContext);
    // No eglTerminate: platform displays are shared per native display, so terminating here would pull
    // the display from under another live context of the same backend.
}

void EglContext::makeCurrent() {
    // EGL skips a make-current of the context it believes current, but OSMesa shares Mesa's glapi
    // dispatch and may have replaced it behind EGL's back: release first so the bind really happens.
    if (eglGetCurrentContext() == mContext)
        eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (!eglMakeCurrent(mDisplay, EGL_NO_SURFACE, EGL_NO_SURFACE, mContext))
        fail("eglMakeCurrent without surface failed (" + eglErrorName(eglGetError()) + ")");
    // An OSMesa context may have steered epoxy's pointers; EGL contexts use epoxy's own resolution.
    EpoxyOsMesaBridge::restore();
}

void EglContext::initializeDisplay() {
    EGLint major = 0, minor = 0;
    if (!eglInitialize(mDisplay, &major, &minor))
        fail("eglInitialize failed (" + eglErrorName(eglGetError()) + ")");
    if (!epoxy_has_egl_extension(mDisplay, "EGL_KHR_create_context"))
        fail("EGL_KHR_create_context missing (cannot ask for a 4.5 compatibility profile)");
    if (!epoxy_has_egl_extension(mDisplay, "EGL_KHR_surfaceless_context"))
        fail("EGL_KHR_surfaceless_context missing (no surface-less make-current)");
    if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API) failed: no desktop OpenGL");
}

EGLConfig EglContext::chooseConfig() const {
    // Rendering goes to FBOs only, so no config is needed where the display allows that.
    if (epoxy_has_egl_extension(mDisplay, "EGL_KHR_no_config_context")) return EGL_NO_CONFIG_KHR;
    const EGLint attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(mDisplay, attributes, &config, 1, &count) || count == 0)
        fail("no EGL config with EGL_OPENGL_BIT (" + eglErrorName(eglGetError()) + ")");
    return config;
}

void EglContext::createGlContext(const ContextOptions& options) {
    const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION_KHR,
                                 4,
                                 EGL_CONTEXT_MINOR_VERSION_KHR,
                                 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK_KHR,
                                 EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT_KHR,
                                 EGL_CONTEXT_FLAGS_KHR,
                                 options.debug ? EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR : 0,
                                 EGL_NONE};
    mContext = eglCreateContext(mDisplay, chooseConfig(), EGL_NO_CONTEXT, attributes);
    if (mContext == EGL_NO_CONTEXT)
        fail("eglCreateContext(OpenGL 4.5 compatibility) failed (" + eglErrorName(eglGetError()) + ")");
}

void EglContext::fail(const std::string& reason) const {
    throw Error(mWhat + ": " + reason, ExitCode::Unsupported);
}

std::string EglContext::eglErrorName(EGLint error) {
    if (const Named<EGLint>* e = kEglErrors.find(error)) return e->name;
    char text[32];
    std::snprintf(text, sizeof text, "EGL error 0x%04x", static_cast<unsigned>(error));
    return text;
}

} // namespace sb
