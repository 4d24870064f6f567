#pragma once
// A GL 4.5 compatibility-profile context, made current on the calling thread on creation. The backends
// that create one live in gl/backends/, one per file, listed in one table (gl/backends/BackendRegistry.h,
// which also has createContext). There is no default framebuffer to render into: everything renders
// into FBOs (FrameTargets).
#include <string>

namespace sb {

/// Which backend made a context; the names are in gl/backends/BackendRegistry.h.
enum class Backend { Auto, EglSurfaceless, EglDevice, OsMesa, Glfw };

struct ContextOptions {
    Backend backend = Backend::Auto;
    int gpu = -1;     ///< EGL device index for egl-device (--gpu N); -1 = first usable
    int width = 1024; ///< window size for glfw; FBO sizes are separate
    int height = 1024;
    bool debug = true;          ///< request a debug context (KHR_debug output is installed by DebugOutput)
    bool visibleWindow = false; ///< glfw only
};

class Context {
public:
    virtual ~Context() = default;
    virtual Backend backend() const = 0;
    virtual void makeCurrent() = 0;
    /// glfw: swap buffers and poll events; others: no-op.
    virtual void present() {}
    /// glfw: true when the window was closed.
    virtual bool shouldClose() const { return false; }
    /// GLFW window handle for the viewer (nullptr for headless backends).
    virtual void* nativeWindow() const { return nullptr; }

    // Filled from glGetString after creation (same for every backend).
    std::string renderer; ///< GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string version;  ///< GL_VERSION, e.g. "4.5 (Compatibility Profile) Mesa 22.3.6"
    std::string vendor;   ///< GL_VENDOR
    std::string glslVersion;
    std::string deviceName; ///< egl-device: the EGL device's name/driver; others: ""
    int glMajor = 0, glMinor = 0;
    bool compatibilityProfile = false;
    /// True for Mesa's software rasterisers (llvmpipe, softpipe, swrast): GL timer queries there do not
    /// measure the frame (docs/ARCHITECTURE.md, "The timing contract"); TimerTrust checks this by
    /// measurement, not by name.
    bool isSoftwareRenderer() const;
    bool hasExtension(const std::string& name) const;
};

} // namespace sb
