#include "bench/lib/callgrind/CostCategory.h"

#include <filesystem>

namespace sb {

namespace {
bool startsWith(const std::string& s, const char* prefix) {
    return s.rfind(prefix, 0) == 0;
}
} // namespace

const char* costCategoryName(CostCategory category) {
    static const char* kNames[kCostCategoryCount] = {"shader_jit", "mesa",   "llvm",
                                                     "harness",    "system", "other"};
    return kNames[int(category)];
}

CostCategory classifyObject(const std::string& object, const std::string& harness) {
    // Callgrind writes "???" for code outside every mapped object file: under llvmpipe that is the code
    // LLVM generated (fragment shaders, the set-up and the vertex pipeline), mapped anonymously.
    if (object.empty() || object == "???") return CostCategory::ShaderJit;
    const std::string file = std::filesystem::path(object).filename().string();
    if (!harness.empty() && (object == harness || file == std::filesystem::path(harness).filename().string()))
        return CostCategory::Harness;
    if (startsWith(file, "libLLVM")) return CostCategory::Llvm;
    // Debian 12's Mesa 22.3 puts llvmpipe into the swrast_dri.so megadriver (EGL, GLX) and into
    // libOSMesa; newer Mesa moves it into libgallium-<version>.so. lavapipe is libvulkan_lvp.so.
    if (file.find("_dri.so") != std::string::npos || startsWith(file, "libgallium") ||
        startsWith(file, "libvulkan_lvp") ||
        startsWith(file, "libOSMesa") || startsWith(file, "libglapi") || startsWith(file, "libEGL_mesa") ||
        startsWith(file, "libGLX_mesa") || startsWith(file, "libgbm"))
        return CostCategory::Mesa;
    for (const char* system : {"libc.so", "libc-", "libm.so", "libm-", "ld-linux", "libstdc++", "libgcc_s",
                               "libpthread", "libdl.so", "librt.so"})
        if (startsWith(file, system)) return CostCategory::System;
    return CostCategory::Other;
}

} // namespace sb
