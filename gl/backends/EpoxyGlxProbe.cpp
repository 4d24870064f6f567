#include "gl/backends/EpoxyGlxProbe.h"

#include <epoxy/gl.h>

#include <dlfcn.h>

#include <mutex>
#include <utility>
#include <vector>

namespace sb {
namespace {

constexpr const char* kPointerName = "epoxy_glXGetCurrentContext";

// GLXContext is an opaque pointer; <epoxy/glx.h> would pull in Xlib for nothing.
using GetCurrentContext = void* (*)();

struct ProbeState {
    std::mutex mutex;
    int users = 0;
    std::vector<std::pair<void**, void*>> saved; ///< pointer variable -> epoxy's value
};

ProbeState& state() {
    static ProbeState s;
    return s;
}

/// The real glXGetCurrentContext of whatever loaded library exports one, or "no GLX context".
void* probe() {
    auto real = reinterpret_cast<GetCurrentContext>(dlsym(RTLD_DEFAULT, "glXGetCurrentContext"));
    return real ? real() : nullptr;
}

/// The executable may hold a copy-relocated instance of the variable (the one RTLD_DEFAULT finds, which
/// every user goes through); epoxy's own copy is written too in case it was linked -Bsymbolic.
std::vector<void**> pointerCopies() {
    std::vector<void**> copies;
    if (auto* global = static_cast<void**>(dlsym(RTLD_DEFAULT, kPointerName))) copies.push_back(global);
    Dl_info info{};
    // A function (not a data pointer) locates the library itself.
    if (dladdr(reinterpret_cast<void*>(&epoxy_has_gl_extension), &info) && info.dli_fname) {
        if (void* handle = dlopen(info.dli_fname, RTLD_NOW | RTLD_NOLOAD)) {
            auto* local = static_cast<void**>(dlsym(handle, kPointerName));
            if (local && (copies.empty() || local != copies.front())) copies.push_back(local);
            dlclose(handle);
        }
    }
    return copies;
}

} // namespace

EpoxyGlxProbe::EpoxyGlxProbe() {
    ProbeState& s = state();
    std::lock_guard lock(s.mutex);
    if (s.users++ > 0) return;
    s.saved.clear();
    for (void** copy : pointerCopies()) {
        s.saved.emplace_back(copy, *copy);
        *copy = reinterpret_cast<void*>(&probe);
    }
}

EpoxyGlxProbe::~EpoxyGlxProbe() {
    ProbeState& s = state();
    std::lock_guard lock(s.mutex);
    if (s.users == 0 || --s.users > 0) return;
    for (auto it = s.saved.rbegin(); it != s.saved.rend(); ++it) *it->first = it->second;
    s.saved.clear();
}

bool EpoxyGlxProbe::installed() {
    ProbeState& s = state();
    std::lock_guard lock(s.mutex);
    return s.users > 0;
}

} // namespace sb
