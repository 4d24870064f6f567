#include "gl/backends/EpoxyOsMesaBridge.h"

// epoxy/gl.h must come before GL/osmesa.h (which includes GL/gl.h).
#include <epoxy/gl.h>

#include <GL/osmesa.h>
#include <dlfcn.h>
#include <elf.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "core/Error.h"

namespace sb {
namespace {

constexpr const char* kPointerPrefix = "epoxy_gl";
constexpr const char* kGlxPrefix = "epoxy_glX"; // GLX entry points stay with epoxy

struct BridgeState {
    std::mutex mutex;
    bool installed = false;
    size_t redirected = 0;
    std::vector<std::pair<void**, void*>> saved; ///< pointer variable -> value before install()
};

BridgeState& state() {
    static BridgeState s;
    return s;
}

bool startsWith(const std::string& s, const char* prefix) {
    return s.rfind(prefix, 0) == 0;
}

std::string epoxyLibraryPath() {
    Dl_info info{};
    // A function (not a data pointer: those may be copy-relocated into the executable) locates the .so.
    if (!dladdr(reinterpret_cast<void*>(&epoxy_has_gl_extension), &info) || !info.dli_fname)
        throw Error("osmesa: cannot locate libepoxy (dladdr failed)", ExitCode::Unsupported);
    return info.dli_fname;
}

/// Names of epoxy's exported GL function-pointer variables, read from the .dynsym of the library file
/// (the loaded image has no section headers mapped, the file does).
std::vector<std::string> epoxyPointerNames(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    std::vector<char> data((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if (data.size() < sizeof(Elf64_Ehdr) || std::memcmp(data.data(), ELFMAG, SELFMAG) != 0)
        throw Error("osmesa: cannot read the ELF symbol table of '" + path + "'", ExitCode::Unsupported);
    const auto* header = reinterpret_cast<const Elf64_Ehdr*>(data.data());
    const auto* sections = reinterpret_cast<const Elf64_Shdr*>(data.data() + header->e_shoff);
    std::vector<std::string> names;
    for (int i = 0; i < header->e_shnum; ++i) {
        if (sections[i].sh_type != SHT_DYNSYM) continue;
        const auto* symbols = reinterpret_cast<const Elf64_Sym*>(data.data() + sections[i].sh_offset);
        const char* strings = data.data() + sections[sections[i].sh_link].sh_offset;
        size_t count = sections[i].sh_size / sizeof(Elf64_Sym);
        for (size_t k = 0; k < count; ++k) {
            if (ELF64_ST_TYPE(symbols[k].st_info) != STT_OBJECT || symbols[k].st_shndx == SHN_UNDEF) continue;
            std::string name = strings + symbols[k].st_name;
            if (startsWith(name, kPointerPrefix) && !startsWith(name, kGlxPrefix)) names.push_back(name);
        }
    }
    if (names.empty())
        throw Error("osmesa: no epoxy_gl* pointers found in '" + path + "'", ExitCode::Unsupported);
    return names;
}

/// Sets one pointer variable, remembering its old value. The executable may hold a copy-relocated
/// instance of the variable (the one RTLD_DEFAULT finds, which everyone uses); the library's own copy
/// is written too in case epoxy was linked -Bsymbolic.
void redirect(BridgeState& s, void* epoxyHandle, const std::string& name, void* function) {
    auto* global = static_cast<void**>(dlsym(RTLD_DEFAULT, name.c_str()));
    auto* local = static_cast<void**>(dlsym(epoxyHandle, name.c_str()));
    if (global) {
        s.saved.emplace_back(global, *global);
        *global = function;
    }
    if (local && local != global) {
        s.saved.emplace_back(local, *local);
        *local = function;
    }
}

} // namespace

void EpoxyOsMesaBridge::install() {
    BridgeState& s = state();
    std::lock_guard lock(s.mutex);
    if (s.installed) return;
    std::string path = epoxyLibraryPath();
    std::vector<std::string> names = epoxyPointerNames(path);
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_NOLOAD);
    s.saved.clear();
    s.redirected = 0;
    for (const std::string& name : names) {
        // "epoxy_glFoo" -> "glFoo". OSMesa answers NULL for what Mesa does not implement: those keep
        // epoxy's resolver (which then reports the missing function itself when called).
        auto function = reinterpret_cast<void*>(OSMesaGetProcAddress(name.c_str() + 6));
        if (!function) continue;
        redirect(s, handle, name, function);
        ++s.redirected;
    }
    if (handle) dlclose(handle);
    s.installed = true;
}

void EpoxyOsMesaBridge::restore() {
    BridgeState& s = state();
    std::lock_guard lock(s.mutex);
    if (!s.installed) return;
    for (auto it = s.saved.rbegin(); it != s.saved.rend(); ++it) *it->first = it->second;
    s.saved.clear();
    s.installed = false;
}

bool EpoxyOsMesaBridge::installed() {
    std::lock_guard lock(state().mutex);
    return state().installed;
}

size_t EpoxyOsMesaBridge::redirectedCount() {
    std::lock_guard lock(state().mutex);
    return state().redirected;
}

} // namespace sb
