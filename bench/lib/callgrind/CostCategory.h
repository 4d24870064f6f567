#pragma once
// Where counted instructions run, by the object file callgrind attributes them to. The categories answer
// "did the shaders get slower, or the driver, or our own code" for a change in instructions per frame.
#include <array>
#include <string>

namespace sb {

enum class CostCategory : int {
    ShaderJit = 0, ///< code in no object file ("???"): llvmpipe's JIT-compiled shaders and set-up functions
    Mesa,          ///< llvmpipe/gallium and Mesa's GL front end: *_dri.so, libgallium*, libOSMesa, libglapi
    Llvm,          ///< libLLVM* (compiling a shader variant inside a measured frame)
    Harness,       ///< the bench binary itself
    System,        ///< libc, libm, the dynamic linker, libstdc++, libgcc_s
    Other,         ///< everything else (libepoxy, the GL dispatch of libglvnd, ...)
};

constexpr int kCostCategoryCount = 6;

/// Per-category instruction counts, indexed by CostCategory.
using CategoryIr = std::array<uint64_t, kCostCategoryCount>;

/// "shader_jit", "mesa", "llvm", "harness", "system", "other": the JSON keys.
const char* costCategoryName(CostCategory category);

/// The category of code in `object` (callgrind's `ob=` path, "???" or "" for no object). `harness` is the
/// bench binary's path as callgrind names it; an object with the same file name counts as the harness.
CostCategory classifyObject(const std::string& object, const std::string& harness);

} // namespace sb
