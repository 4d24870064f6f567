#include "core/DriverTable.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/Error.h"
#include "core/Suggestion.h"

namespace sb {

namespace {

namespace fs = std::filesystem;

constexpr const char* kActiveVariable = "SHADOWBENCH_DRIVER";
/// A variable a driver replaced keeps its earlier value here ("<prefix>LD_LIBRARY_PATH"); one that was
/// unset is listed in kUnsetVariable, so `activate` can restore either.
constexpr const char* kSavedPrefix = "SHADOWBENCH_DRIVER_SAVED_";
constexpr const char* kUnsetVariable = "SHADOWBENCH_DRIVER_UNSET";

/// Every variable a driver may set: restored before another driver's are set.
const std::vector<std::string>& driverVariables() {
    static const std::vector<std::string> kVariables = {
        "LD_LIBRARY_PATH",  "LIBGL_DRIVERS_PATH", "__EGL_VENDOR_LIBRARY_FILENAMES",
        "VK_ICD_FILENAMES", "VK_DRIVER_FILES",    "GBM_BACKENDS_PATH"};
    return kVariables;
}

struct NamedDriver {
    const char* name;
    const char* folder;  ///< under driversDirectory(); "" for the system driver
    const char* install; ///< how to get it
};

constexpr NamedDriver kNamed[] = {
    {"system", "", "the system's Mesa packages (bash scripts/install-deps.sh bench)"},
    {"mesa-25.0.7", "mesa-25.0.7", "bash scripts/install-deps.sh driver"},
};

std::string env(const char* name) {
    const char* v = std::getenv(name);
    return v ? v : "";
}

bool present(const fs::path& p) {
    std::error_code ec;
    return fs::exists(p, ec);
}

/// The prefix's library folder: where `meson install` (lib/<triple>, lib64, lib) or `dpkg -x`
/// (usr/lib/<triple>) put libEGL_mesa.so.0 or libvulkan_lvp.so.
fs::path libraryFolder(const fs::path& prefix) {
    for (const char* sub : {"usr/lib/x86_64-linux-gnu", "lib/x86_64-linux-gnu", "usr/lib/aarch64-linux-gnu",
                            "lib/aarch64-linux-gnu", "usr/lib64", "lib64", "usr/lib", "lib"}) {
        const fs::path dir = prefix / sub;
        if (present(dir / "libEGL_mesa.so.0") || present(dir / "libvulkan_lvp.so")) return dir;
    }
    return {};
}

/// The first of `candidates` (relative to prefix) that exists, or the first file in `folder` whose name
/// starts with `stem`; "" when none.
std::string findFile(const fs::path& prefix, std::initializer_list<const char*> candidates,
                     std::initializer_list<const char*> folders, const std::string& stem) {
    for (const char* c : candidates)
        if (present(prefix / c)) return (prefix / c).string();
    for (const char* f : folders) {
        std::error_code ec;
        for (const auto& entry : fs::directory_iterator(prefix / f, ec))
            if (entry.path().filename().string().rfind(stem, 0) == 0) return entry.path().string();
    }
    return "";
}

std::string joined(const std::vector<std::string>& items) {
    std::string out;
    for (const std::string& i : items) out += (out.empty() ? "" : ", ") + i;
    return out;
}

/// The variables that choose a driver's libraries; LD_LIBRARY_PATH is left out because it is commonly
/// set for other reasons.
bool selectingVariableSet() {
    for (const std::string& v : driverVariables())
        if (v != "LD_LIBRARY_PATH" && std::getenv(v.c_str())) return true;
    return false;
}

void restoreSaved() {
    for (const std::string& v : driverVariables()) {
        const std::string saved = std::string(kSavedPrefix) + v;
        if (const char* old = std::getenv(saved.c_str())) {
            ::setenv(v.c_str(), old, 1);
            ::unsetenv(saved.c_str());
        }
    }
    const std::string unset = env(kUnsetVariable);
    size_t at = 0;
    while (at < unset.size()) {
        const size_t end = std::min(unset.find(':', at), unset.size());
        ::unsetenv(unset.substr(at, end - at).c_str());
        at = end + 1;
    }
    ::unsetenv(kUnsetVariable);
    ::unsetenv(kActiveVariable);
}

} // namespace

std::vector<std::string> DriverTable::names() {
    std::vector<std::string> out;
    for (const NamedDriver& d : kNamed) out.emplace_back(d.name);
    return out;
}

std::string DriverTable::driversDirectory() {
    const std::string dir = env("SHADOWBENCH_DRIVERS_DIR");
    return dir.empty() ? "/opt/shadowbench/drivers" : dir;
}

std::vector<std::pair<std::string, std::string>> DriverTable::environmentOf(const std::string& prefix) {
    const fs::path p(prefix);
    const fs::path lib = libraryFolder(p);
    if (lib.empty())
        throw Error("--driver " + prefix +
                        ": no Mesa driver in this prefix (no libEGL_mesa.so.0 or libvulkan_lvp.so under "
                        "usr/lib/x86_64-linux-gnu, lib/x86_64-linux-gnu, lib64 or lib)",
                    ExitCode::Unsupported);
    std::vector<std::pair<std::string, std::string>> out;
    const std::string before = env("LD_LIBRARY_PATH");
    out.emplace_back("LD_LIBRARY_PATH", lib.string() + (before.empty() ? "" : ":" + before));
    if (present(lib / "dri")) out.emplace_back("LIBGL_DRIVERS_PATH", (lib / "dri").string());
    // The files scripts/install-deps.sh writes name the libraries by absolute path; a meson prefix's own
    // files name them by file name, which LD_LIBRARY_PATH above resolves to the prefix.
    const std::string vendor = findFile(
        p, {"etc/egl_vendor.json"}, {"usr/share/glvnd/egl_vendor.d", "share/glvnd/egl_vendor.d"}, "50_mesa");
    if (!vendor.empty() && present(lib / "libEGL_mesa.so.0"))
        out.emplace_back("__EGL_VENDOR_LIBRARY_FILENAMES", vendor);
    const std::string icd =
        findFile(p, {"etc/lvp_icd.json"}, {"usr/share/vulkan/icd.d", "share/vulkan/icd.d"}, "lvp_icd");
    if (!icd.empty() && present(lib / "libvulkan_lvp.so")) {
        out.emplace_back("VK_ICD_FILENAMES", icd);
        out.emplace_back("VK_DRIVER_FILES", icd); // the newer loader's name for it, which wins when set
    }
    if (present(lib / "gbm")) out.emplace_back("GBM_BACKENDS_PATH", (lib / "gbm").string());
    return out;
}

Driver DriverTable::resolve(const std::string& nameOrPath) {
    if (nameOrPath.find('/') != std::string::npos) {
        std::error_code ec;
        const fs::path p = fs::absolute(nameOrPath, ec);
        if (!fs::is_directory(p, ec))
            throw Error("--driver " + nameOrPath + ": no such folder (a driver is a name: " +
                        joined(names()) + ", or a Mesa install prefix)");
        const std::string prefix = fs::weakly_canonical(p, ec).string();
        return {prefix, prefix, environmentOf(prefix)};
    }
    for (const NamedDriver& d : kNamed) {
        if (nameOrPath != d.name) continue;
        if (!*d.folder) return {d.name, "", {}};
        const std::string prefix = (fs::path(driversDirectory()) / d.folder).string();
        if (!present(prefix))
            throw Error("--driver " + nameOrPath + ": not installed (no " + prefix +
                            "); install it with: " + d.install,
                        ExitCode::Unsupported);
        return {d.name, prefix, environmentOf(prefix)};
    }
    throw Error("--driver " + nameOrPath + ": unknown driver" + Suggestion::didYouMean(nameOrPath, names()) +
                " (the drivers: " + joined(names()) + ", or a Mesa install prefix's path)");
}

std::string DriverTable::requested(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--") break;
        if (a.rfind("--driver=", 0) == 0) {
            if (a.size() == 9) throw Error("--driver: expected a driver name or a prefix path");
            return a.substr(9);
        }
        if (a == "--driver") {
            if (i + 1 >= argc || argv[i + 1][0] == '\0')
                throw Error("--driver: expected a driver name or a prefix path");
            return argv[i + 1];
        }
    }
    return "";
}

std::string DriverTable::current() {
    const std::string name = env(kActiveVariable);
    if (!name.empty()) return name;
    // Variables set by hand (not by --driver) choose libraries this table cannot name.
    return selectingVariableSet() ? "environment" : "system";
}

std::vector<std::string> DriverTable::carriedVariables() {
    std::vector<std::string> out = driverVariables();
    out.emplace_back(kActiveVariable);
    return out;
}

bool DriverTable::isActive(const Driver& driver) {
    if (current() != driver.name) return false;
    for (const auto& [name, value] : driver.environment)
        if (name != "LD_LIBRARY_PATH" && env(name.c_str()) != value) return false;
    return true;
}

void DriverTable::activate(const Driver& driver) {
    restoreSaved();
    if (driver.prefix.empty()) // the system's libraries: none of the variables that choose others
        for (const std::string& v : driverVariables())
            if (v != "LD_LIBRARY_PATH") ::unsetenv(v.c_str());
    std::string unset;
    for (const auto& [name, value] : driver.environment) {
        if (const char* old = std::getenv(name.c_str()))
            ::setenv((std::string(kSavedPrefix) + name).c_str(), old, 1);
        else
            unset += (unset.empty() ? "" : ":") + name;
        ::setenv(name.c_str(), value.c_str(), 1);
    }
    if (!unset.empty()) ::setenv(kUnsetVariable, unset.c_str(), 1);
    if (!driver.prefix.empty()) ::setenv(kActiveVariable, driver.name.c_str(), 1);
}

std::vector<std::pair<std::string, std::string>> DriverTable::childEnvironment(const Driver& driver) {
    if (current() != "system")
        throw Error("this run is on the driver " + current() +
                    "; start a comparison of drivers from the system driver (no --driver before it)");
    auto out = driver.environment;
    if (!driver.prefix.empty()) out.emplace_back(kActiveVariable, driver.name);
    return out;
}

namespace {

/// The `ICD.library_path` of a glvnd vendor file or a Vulkan ICD file; "" when the file says none.
std::string icdLibrary(const std::string& file) {
    std::ifstream in(file);
    if (!in)
        throw Error("--driver " + DriverTable::current() + ": cannot read " + file, ExitCode::Unsupported);
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.contains("ICD") || !j["ICD"].contains("library_path") ||
        !j["ICD"]["library_path"].is_string())
        throw Error("--driver " + DriverTable::current() + ": " + file + " names no ICD.library_path",
                    ExitCode::Unsupported);
    const std::string path = j["ICD"]["library_path"].get<std::string>();
    // The loaders read a relative path with a '/' from the file's folder, a bare name through the
    // library search path (as dlopen does).
    if (path.find('/') == std::string::npos || fs::path(path).is_absolute()) return path;
    return (fs::path(file).parent_path() / path).string();
}

} // namespace

namespace {

const char* apiLibraryName(DriverTable::Api api) {
    return api == DriverTable::Api::GL ? "GL (EGL vendor)" : "Vulkan (ICD)";
}

} // namespace

std::string DriverTable::libraryToLoad(Api api) {
    const std::string name = current();
    if (name == "system" || name == "environment") return "";
    const char* variable = api == Api::GL ? "__EGL_VENDOR_LIBRARY_FILENAMES" : "VK_ICD_FILENAMES";
    const std::string file = env(variable);
    if (file.empty())
        throw Error("--driver " + name + ": no " + apiLibraryName(api) + " library in this driver (" +
                        variable + " unset)",
                    ExitCode::Unsupported);
    return icdLibrary(file);
}

Error DriverTable::cannotLoad(Api api, const char* why) {
    return Error("--driver " + current() + ": its " + apiLibraryName(api) +
                     " library cannot load: " + (why ? why : "unknown reason"),
                 ExitCode::Unsupported);
}

std::string DriverTable::versionInGlVersion(const std::string& glVersion) {
    const size_t mesa = glVersion.find("Mesa ");
    return mesa == std::string::npos ? glVersion : glVersion.substr(mesa);
}

} // namespace sb
