#include "gl/backends/BackendRegistry.h"

#include <epoxy/gl.h>

#include <dlfcn.h>
#include <optional>
#include <vector>

#include "core/DriverShaderCache.h"
#include "core/DriverTable.h"
#include "core/Error.h"
#include "core/NameTable.h"
#include "gl/backends/EglDeviceContext.h"
#include "gl/backends/EglSurfacelessContext.h"
#include "gl/backends/GlfwContext.h"
#include "gl/backends/OsMesaContext.h"

namespace sb {
namespace {

constexpr int kRequiredMajor = 4;
constexpr int kRequiredMinor = 5;
constexpr const char* kAutoName = "auto";

template <typename T>
std::unique_ptr<Context> make(const ContextOptions& options) {
    return std::make_unique<T>(options);
}

using AutoUse = BackendEntry::AutoUse;
// The one table of backends. Order is the order of --help.
constexpr BackendEntry kBackends[] = {
    {Backend::EglSurfaceless, "egl-surfaceless", AutoUse::Always, true, make<EglSurfacelessContext>},
    {Backend::EglDevice, "egl-device", AutoUse::WithGpu, true, make<EglDeviceContext>},
    {Backend::OsMesa, "osmesa", AutoUse::Always, true, make<OsMesaContext>},
    {Backend::Glfw, "glfw", AutoUse::Never, false, make<GlfwContext>},
};

constexpr NameTable kBackendTable{kBackends};

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

/// "" when the context is good enough, else why not. Immediate mode and display lists (the
/// `immediate` and `displaylist` submitters) exist only in the compatibility profile.
std::string checkRequirements(const Context& context) {
    bool versionOk = context.glMajor > kRequiredMajor ||
                     (context.glMajor == kRequiredMajor && context.glMinor >= kRequiredMinor);
    if (!versionOk) return "got OpenGL " + context.version + ", need 4.5";
    if (!context.compatibilityProfile)
        return "got a core-profile context (" + context.version + "), need compatibility";
    return "";
}

std::vector<const BackendEntry*> candidates(const ContextOptions& options) {
    if (options.backend != Backend::Auto) return {kBackendTable.find(options.backend)};
    std::vector<const BackendEntry*> order;
    if (options.gpu >= 0)
        for (const BackendEntry& e : kBackends)
            if (e.autoUse == AutoUse::WithGpu) order.push_back(&e);
    for (const BackendEntry& e : kBackends)
        if (e.autoUse == AutoUse::Always) order.push_back(&e);
    return order;
}

/// A context that exists but is below 4.5 compatibility is refused with ExitCode::Unsupported like a
/// backend that failed; in Auto mode the next backend still gets its chance. A backend that finds the
/// user's input wrong (ExitCode::BadInput) ends the search.
std::unique_ptr<Context> tryBackend(const BackendEntry& backend, const ContextOptions& options,
                                    std::string& reason) {
    try {
        std::unique_ptr<Context> context = backend.create(options);
        queryInfo(*context);
        reason = checkRequirements(*context);
        if (reason.empty()) return context;
        reason = std::string(backend.name) + ": " + reason;
    } catch (const Error& e) {
        // Bad input (a device index out of range) is not a reason to try the next backend.
        if (e.code() == ExitCode::BadInput) throw;
        reason = e.what();
    }
    return nullptr;
}

} // namespace

std::span<const BackendEntry> BackendRegistry::entries() {
    return kBackends;
}

const char* backendName(Backend b) {
    if (b == Backend::Auto) return kAutoName;
    return kBackendTable.name(b);
}

Backend parseBackend(const std::string& name) {
    if (name == kAutoName) return Backend::Auto;
    if (std::optional<Backend> b = kBackendTable.parse(name)) return *b;
    throw Error("unknown backend '" + name + "' (valid: " + backendNames() + ")", ExitCode::BadInput);
}

std::string backendNames(bool headlessOnly) {
    std::string out = kAutoName;
    for (const BackendEntry& e : kBackends)
        if (e.headless || !headlessOnly) out += std::string(", ") + e.name;
    return out;
}

std::unique_ptr<Context> createContext(const ContextOptions& options) {
    DriverShaderCache::separateByVectorWidth(); // before the driver opens its shader cache
    // Loaded once here and kept: glvnd, which opens it next, gets the same handle.
    const std::string driverLibrary = DriverTable::libraryToLoad(DriverTable::Api::GL);
    if (!driverLibrary.empty() && !::dlopen(driverLibrary.c_str(), RTLD_LAZY | RTLD_LOCAL))
        throw DriverTable::cannotLoad(DriverTable::Api::GL, ::dlerror());
    std::string reasons;
    for (const BackendEntry* backend : candidates(options)) {
        if (!backend) throw Error("createContext: no backend for this Backend value", ExitCode::Failure);
        std::string reason;
        if (std::unique_ptr<Context> context = tryBackend(*backend, options, reason)) return context;
        reasons += (reasons.empty() ? "" : "; ") + reason;
    }
    throw Error("no OpenGL 4.5 compatibility context (backend " + std::string(backendName(options.backend)) +
                    "): " + reasons,
                ExitCode::Unsupported);
}

} // namespace sb
