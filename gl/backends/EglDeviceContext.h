#pragma once
// egl-device: an EGLDevice (EGL_EXT_device_enumeration + EGL_EXT_platform_device) picked by --gpu N,
// for machines with several GPUs and no display server. Mesa also lists a software device
// (EGL_MESA_device_software), so this backend works on llvmpipe too.
#include <string>
#include <vector>

#include "gl/backends/EglContext.h"

namespace sb {

class EglDeviceContext : public EglContext {
public:
    /// options.gpu >= 0 picks that device; -1 takes device 0. Throws
    /// sb::Error("egl-device: <reason>", ExitCode::Unsupported), e.g. an index out of range.
    explicit EglDeviceContext(const ContextOptions& options);
    Backend backend() const override { return Backend::EglDevice; }

    /// The devices EGL reports (empty when the extensions are missing).
    static std::vector<EGLDeviceEXT> enumerateDevices();
    /// "software (EGL_MESA_device_software)", "/dev/dri/renderD128" ... for the CSV's device column.
    static std::string describeDevice(EGLDeviceEXT device);

private:
    struct PickedDevice {
        EGLDeviceEXT device;
        int index;
    };
    EglDeviceContext(const PickedDevice& picked, const ContextOptions& options);
    static PickedDevice pickDevice(const ContextOptions& options);
    static EGLDisplay openDisplay(EGLDeviceEXT device);
    /// ApitraceHandoff::toEglTracer(), then `options` (runs before pickDevice's EGL calls).
    static const ContextOptions& handOff(const ContextOptions& options);
};

} // namespace sb
