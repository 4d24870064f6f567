#pragma once
// Which GL and Vulkan driver build a process loads: the driver axis of every command that renders.
//
// A driver is chosen by the libraries the dynamic loader and the two ICD loaders (glvnd's libEGL and the
// Vulkan loader) pick, and they read their search paths once, at process start (LD_LIBRARY_PATH) or at
// the first context (the vendor and ICD files). So a driver is an environment, and `--driver` applies it
// by running the same program again with that environment (BenchApp::main), the way a driver developer
// points a shell at a `meson install` prefix. `--backend`, `--gpu` and `--vk-device` keep their meaning
// inside the chosen driver.
//
// The table has two named entries, and any Mesa install prefix may be given by its path:
//   system        the libraries the system's packages installed (Debian 12: Mesa 22.3.6); no variable set
//   mesa-25.0.7   Mesa 25.0.7 from Debian's bookworm-backports suite, unpacked (not installed) into
//                 <drivers>/mesa-25.0.7 by `bash scripts/install-deps.sh driver`
//   PATH          a prefix holding a Mesa build (`meson install --destdir`, or `dpkg -x` of Mesa's packages)
// <drivers> is $SHADOWBENCH_DRIVERS_DIR, else /opt/shadowbench/drivers.
#include <string>
#include <utility>
#include <vector>

#include "core/Error.h"

namespace sb {

struct Driver {
    std::string name;   ///< "system", "mesa-25.0.7", or the prefix's absolute path
    std::string prefix; ///< "" for the system driver
    /// The variables that select it, in the order they are set (empty for the system driver).
    std::vector<std::pair<std::string, std::string>> environment;
};

class DriverTable {
public:
    /// The named entries, in --help's order: {"system", "mesa-25.0.7"}.
    static std::vector<std::string> names();
    /// Where named prefixes live: $SHADOWBENCH_DRIVERS_DIR, else /opt/shadowbench/drivers.
    static std::string driversDirectory();
    /// A name of the table or a prefix path (anything with a '/'). Throws Error: BadInput for an unknown
    /// name (with the names) or a path that does not exist; Unsupported (exit 3) for a named driver that
    /// is not installed (saying how to install it) or a prefix that holds no Mesa driver.
    static Driver resolve(const std::string& nameOrPath);
    /// The variables of the driver found in `prefix`: its library folder in LD_LIBRARY_PATH, its dri/
    /// and gbm/ folders, its glvnd vendor file and its lavapipe ICD file. Throws Unsupported when the
    /// prefix holds neither libEGL_mesa.so.0 nor libvulkan_lvp.so.
    static std::vector<std::pair<std::string, std::string>> environmentOf(const std::string& prefix);

    /// The value of `--driver NAME` or `--driver=NAME` in argv (before a "--"), or "" when absent.
    /// Throws BadInput when the option has no value.
    static std::string requested(int argc, char** argv);
    /// The driver this process runs on: the name a `--driver` run set ($SHADOWBENCH_DRIVER), else
    /// "system". Recorded in every row (the `driver` column).
    static std::string current();
    /// The variables that carry the driver this process runs on to a child started with an environment
    /// of its own (valgrind's): the ones any driver sets and the name --driver gave it.
    static std::vector<std::string> carriedVariables();
    /// True when this process already runs with `driver`'s environment (so no re-run is needed).
    static bool isActive(const Driver& driver);
    /// Sets `driver`'s variables in this process's environment (restoring the values a previous driver
    /// replaced, so `--driver system` inside a driver's run is the system again) and names it in
    /// SHADOWBENCH_DRIVER. The libraries already loaded are not changed: the caller runs itself again.
    static void activate(const Driver& driver);
    /// The variables a child process needs to run on `driver` when this process runs on the system
    /// driver: its environment and SHADOWBENCH_DRIVER. Throws BadInput when this process already runs on
    /// another driver (a child could not return to the system's libraries by adding variables).
    static std::vector<std::pair<std::string, std::string>> childEnvironment(const Driver& driver);
    /// The library of one API a driver's ICD file names: glvnd's EGL vendor library or the Vulkan ICD.
    enum class Api { GL, Vulkan };
    /// The library through which `api` reaches the driver this process runs on (the one its vendor or
    /// ICD file names), for the caller to load before it creates a context or instance, so that a prefix
    /// whose library cannot load is refused in one line (cannotLoad) instead of by a loader's failure
    /// (or, on GL, a silent fall back to another backend). "" on the system driver or one set by hand
    /// ("environment"): nothing to check. Throws Unsupported when the driver has no such file for `api`
    /// or the file names no library.
    static std::string libraryToLoad(Api api);
    /// The one-line refusal (ExitCode::Unsupported) of a library libraryToLoad named that did not load;
    /// `why` is the loader's message (dlerror()), which names the library.
    static Error cannotLoad(Api api, const char* why);
    /// The driver's version in a GL_VERSION string: from "Mesa " on ("4.5 (Compatibility Profile) Mesa
    /// 25.0.7-2~bpo12+1" gives "Mesa 25.0.7-2~bpo12+1"), the whole string for a driver that is not Mesa.
    static std::string versionInGlVersion(const std::string& glVersion);
};

} // namespace sb
