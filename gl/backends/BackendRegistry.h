#pragma once
// The context backends, in one table (BackendRegistry.cpp): each row names a backend, says when
// `--backend auto` tries it and whether it runs without a display, and creates it. --backend's help
// text, its errors and the auto order all come from the table, so adding a backend is one file pair in
// gl/backends/, one value of Backend (gl/Context.h) and one row.
#include <memory>
#include <span>
#include <string>

#include "gl/Context.h"

namespace sb {

struct BackendEntry {
    /// When `auto` tries a backend: never (only when asked for by name), only when --gpu picks a device,
    /// or always; the backends auto tries are tried in table order, the --gpu ones first.
    enum class AutoUse { Never, WithGpu, Always };

    Backend value;
    const char* name; ///< --backend value and the CSV's `backend` column
    AutoUse autoUse;
    bool headless; ///< needs no display (sweeps and figures run only these)
    std::unique_ptr<Context> (*create)(const ContextOptions& options);
};

class BackendRegistry {
public:
    /// The concrete backends (not `auto`), in the order --help lists them.
    static std::span<const BackendEntry> entries();
};

/// "auto", "egl-surfaceless", "egl-device", "osmesa", "glfw".
const char* backendName(Backend b);
/// Throws sb::Error(BadInput) listing the valid names.
Backend parseBackend(const std::string& name);
/// "auto, egl-surfaceless, egl-device, osmesa, glfw" (`headlessOnly`: without the window backends).
std::string backendNames(bool headlessOnly = false);

/// Creates a context: Auto tries egl-device when --gpu is given, then egl-surfaceless, then osmesa
/// (glfw only when asked for). Throws sb::Error with every backend's failure reason when none works,
/// or when the context is not >= 4.5 compatibility (ExitCode::Unsupported).
std::unique_ptr<Context> createContext(const ContextOptions& options);

} // namespace sb
