#include "core/DriverShaderCache.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace sb {

namespace fs = std::filesystem;

namespace {

std::string environment(const char* name) {
    const char* value = std::getenv(name);
    return value ? value : "";
}

/// The folder Mesa's disk cache puts its own `mesa_shader_cache` folder in (util/disk_cache_os.c's order).
fs::path driverBase() {
    if (std::string dir = environment("MESA_SHADER_CACHE_DIR"); !dir.empty()) return dir;
    if (std::string xdg = environment("XDG_CACHE_HOME"); !xdg.empty()) return xdg;
    if (std::string home = environment("HOME"); !home.empty()) return fs::path(home) / ".cache";
    return {};
}

} // namespace

std::string DriverShaderCache::folderName(const std::string& width) {
    return "mesa-lp-vector-width-" + width;
}

std::string DriverShaderCache::separateByVectorWidth() {
    const std::string width = environment("LP_NATIVE_VECTOR_WIDTH");
    if (width.empty()) return "";
    const bool number = std::all_of(width.begin(), width.end(), [](char c) { return std::isdigit(c) != 0; });
    const fs::path base = driverBase();
    if (number && !base.empty()) {
        // A child process inherits the folder its parent set: keep it rather than nest another.
        if (base.filename() == folderName(width)) return base.string();
        const fs::path folder = base / folderName(width);
        std::error_code ec;
        fs::create_directories(folder, ec);
        if (!ec) {
            setenv("MESA_SHADER_CACHE_DIR", folder.c_str(), 1);
            return folder.string();
        }
    }
    // No folder of its own: no cache at all rather than another width's code.
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    return "disabled";
}

} // namespace sb
