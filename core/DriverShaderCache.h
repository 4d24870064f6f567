#pragma once
// Keeps Mesa llvmpipe's on-disk shader cache apart per SIMD width. llvmpipe (and lavapipe, which runs on
// it) keys its cache by the CPU's features but not by LP_NATIVE_VECTOR_WIDTH (Mesa 22.3, the CI
// platform), so a run with LP_NATIVE_VECTOR_WIDTH=128 on a machine whose default is 256 bits loads the
// machine code its 256-bit runs compiled. Measured on llvmpipe 22.3.6: one 256-bit run of `-t occluder`
// fills the cache, and every later 128-bit run of it (and of `-t hybrid`, `-t auto`) aborts with heap
// corruption inside the driver's draw; with a cache of its own the 128-bit run draws the 256-bit run's
// images. A machine whose default is 128 bits (no AVX, ARM) never mixes widths and is left alone.
#include <string>

namespace sb {

struct DriverShaderCache {
    /// Call before a GL context or a Vulkan instance is created (the driver reads its cache folder then).
    /// When LP_NATIVE_VECTOR_WIDTH is set in the environment, sets MESA_SHADER_CACHE_DIR to the folder
    /// `mesa-lp-vector-width-<value>` under the folder the driver uses otherwise (MESA_SHADER_CACHE_DIR,
    /// else $XDG_CACHE_HOME, else $HOME/.cache), creating it; a value that is not a whole number, or no
    /// such base folder, sets MESA_SHADER_CACHE_DISABLE=true instead. Idempotent: a process (or its child)
    /// already pointed at the width's folder keeps it. Returns the folder set, "disabled", or "" when the
    /// variable is unset and nothing changed.
    static std::string separateByVectorWidth();
    /// The folder name for a LP_NATIVE_VECTOR_WIDTH value: "mesa-lp-vector-width-128".
    static std::string folderName(const std::string& width);
};

} // namespace sb
