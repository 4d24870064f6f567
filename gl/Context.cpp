#include "gl/Context.h"

#include <epoxy/gl.h>

#include <array>
#include <functional>
#include <utility>
#include <vector>

#include "core/Error.h"
#include "gl/EglDeviceContext.h"
#include "gl/EglSurfacelessContext.h"
#include "gl/GlfwContext.h"
#include "gl/OsMesaContext.h"

namespace sb {
namespace {

constexpr int kRequiredMajor = 4;
constexpr int kRequiredMinor = 5;
constexpr std::array kBackends = {Backend::Auto, Backend::EglSurfaceless, Backend::EglDevice, Backend::OsMesa,
                                  Backend::Glfw};
constexpr std::array kSoftwareRenderers = {"llvmpipe", "softpipe", "swrast"};

std::string glString(GLenum name) {
    const GLubyte* value = glGetString(name);
    return value ? reinterpret_cast<const char*>(value) : "";
}

void queryInfo(Context& context) {
    context.renderer = glString(GL_RENDERER);
    context.version = glString(GL_VERSION);
    context.vendor = glString(GL_VENDOR);
    context.glslVersion = glString(GL_SHADING_LANGUAGE_VERSION);
    glGetIntegerv(GL_MAJOR_VERSION, &context.glMajor);
    glGetIntegerv(GL_MINOR_VERSION, &context.glMinor);
    GLint profile = 0;
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    context.compatibilityProfile = (profile & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT) != 0;
}

/// "" when the context is good enough, else why not. Immediate mode and display lists (DESIGN.md
/// section 5) exist only in the compatibility profile.
std::string checkRequirements(const Context& context) {
    bool versionOk = context.glMajor > kRequiredMajor ||
                     (context.glMajor == kRequiredMajor && context.glMinor >= kRequiredMinor);
    if (!versionOk) return "got OpenGL " + context.version + ", need 4.5";
    if (!context.compatibilityProfile)
        return "got a core-profile context (" + context.version + "), need compatibility";
    return "";
}

std::unique_ptr<Context> construct(Backend backend, const ContextOptions& options) {
    switch (backend) {
    case Backend::EglSurfaceless:
        return std::make_unique<EglSurfacelessContext>(options);
    case Backend::EglDevice:
        return std::make_unique<EglDeviceContext>(options);
    case Backend::OsMesa:
        return std::make_unique<OsMesaContext>(options);
    case Backend::Glfw:
        return std::make_unique<GlfwContext>(options);
    case Backend::Auto:
        break;
    }
    throw Error("createContext: Backend::Auto is not a concrete backend", ExitCode::Failure);
}

std::vector<Backend> candidates(const ContextOptions& options) {
    if (options.backend != Backend::Auto) return {options.backend};
    std::vector<Backend> order;
    if (options.gpu >= 0) order.push_back(Backend::EglDevice);
    order.push_back(Backend::EglSurfaceless);
    order.push_back(Backend::OsMesa);
    return order;
}

/// A context that exists but is below 4.5 compatibility is refused with ExitCode::Unsupported like a
/// backend that failed; in Auto mode the next backend still gets its chance.
std::unique_ptr<Context> tryBackend(Backend backend, const ContextOptions& options, std::string& reason) {
    try {
        std::unique_ptr<Context> context = construct(backend, options);
        queryInfo(*context);
        reason = checkRequirements(*context);
        if (reason.empty()) return context;
        reason = std::string(backendName(backend)) + ": " + reason;
    } catch (const Error& e) {
        reason = e.what();
    }
    return nullptr;
}

} // namespace

const char* backendName(Backend b) {
    switch (b) {
    case Backend::Auto:
        return "auto";
    case Backend::EglSurfaceless:
        return "egl-surfaceless";
    case Backend::EglDevice:
        return "egl-device";
    case Backend::OsMesa:
        return "osmesa";
    case Backend::Glfw:
        return "glfw";
    }
    return "?";
}

Backend parseBackend(const std::string& name) {
    std::string valid;
    for (Backend b : kBackends) {
        if (name == backendName(b)) return b;
        valid += std::string(valid.empty() ? "" : ", ") + backendName(b);
    }
    throw Error("unknown backend '" + name + "' (valid: " + valid + ")", ExitCode::BadInput);
}

bool Context::isSoftwareRenderer() const {
    for (const char* name : kSoftwareRenderers)
        if (renderer.find(name) != std::string::npos) return true;
    return false;
}

bool Context::hasExtension(const std::string& name) const {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const GLubyte* extension = glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i));
        if (extension && name == reinterpret_cast<const char*>(extension)) return true;
    }
    return false;
}

std::unique_ptr<Context> createContext(const ContextOptions& options) {
    std::string reasons;
    for (Backend backend : candidates(options)) {
        std::string reason;
        if (std::unique_ptr<Context> context = tryBackend(backend, options, reason)) return context;
        reasons += (reasons.empty() ? "" : "; ") + reason;
    }
    throw Error("no OpenGL 4.5 compatibility context (backend " + std::string(backendName(options.backend)) +
                    "): " + reasons,
                ExitCode::Unsupported);
}

} // namespace sb
