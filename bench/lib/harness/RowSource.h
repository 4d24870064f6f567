#pragma once
// What a result row and the console header take from the run that measured it, whichever API ran it
// (bench/lib/harness/Harness.h on GL, bench/lib/harness/VulkanHarness.h on Vulkan): the configuration, the
// scene, the timer verdict and how the API names its device.
#include <string>

#include "bench/lib/harness/TimerTrust.h"
#include "bench/lib/options/RunConfig.h"
#include "scenes/Scene.h"

namespace sb {

struct RowSource {
    const RunConfig& config;
    const Scene& scene;
    const std::string& contentHash;
    bool moving = false;
    const TimerVerdict& verdict;
    std::string api;           ///< "gl" or "vulkan" (the CSV's `api`)
    std::string apiVersion;    ///< GL_VERSION, or the Vulkan device's API version ("1.3.230")
    std::string renderer;      ///< GL_RENDERER, or the Vulkan device name
    std::string glVersion;     ///< GL_VERSION on GL, empty on Vulkan
    std::string vendor;        ///< GL_VENDOR, or the Vulkan driver (name and info)
    std::string backend;       ///< the GL context backend, or "vulkan"
    std::string device;        ///< EGL device name (egl-device) or the Vulkan device index and name
    std::string driverVersion; ///< the driver's own version (the CSV's `driver_version`)
};

} // namespace sb
