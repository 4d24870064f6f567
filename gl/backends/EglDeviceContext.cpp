#include "gl/backends/EglDeviceContext.h"

#include "core/Error.h"
#include "gl/backends/ApitraceHandoff.h"

namespace sb {
namespace {

constexpr int kMaxDevices = 32;
#ifndef EGL_DRM_RENDER_NODE_FILE_EXT
constexpr EGLint EGL_DRM_RENDER_NODE_FILE_EXT = 0x3377; // EGL_EXT_device_drm_render_node
#endif

[[noreturn]] void failDevice(const std::string& reason) {
    throw Error("egl-device: " + reason, ExitCode::Unsupported);
}

bool hasDeviceExtension(EGLDeviceEXT device, const std::string& name) {
    const char* extensions = eglQueryDeviceStringEXT(device, EGL_EXTENSIONS);
    if (!extensions) return false;
    std::string list = std::string(" ") + extensions + " ";
    return list.find(" " + name + " ") != std::string::npos;
}

const char* deviceString(EGLDeviceEXT device, EGLint name) {
    const char* value = eglQueryDeviceStringEXT(device, name);
    eglGetError(); // an unsupported name sets EGL_BAD_PARAMETER; it is only a missing detail here
    return value;
}

} // namespace

EglDeviceContext::EglDeviceContext(const ContextOptions& options)
    : EglDeviceContext(pickDevice(handOff(options)), options) {}

const ContextOptions& EglDeviceContext::handOff(const ContextOptions& options) {
    // Before the first EGL call (device enumeration): a GLX tracer would record none of them.
    ApitraceHandoff::toEglTracer();
    return options;
}

EglDeviceContext::EglDeviceContext(const PickedDevice& picked, const ContextOptions& options)
    : EglContext(openDisplay(picked.device), options, "egl-device " + std::to_string(picked.index)) {
    deviceName = "device " + std::to_string(picked.index) + ": " + describeDevice(picked.device);
}

std::vector<EGLDeviceEXT> EglDeviceContext::enumerateDevices() {
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_enumeration") ||
        !epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_device_query"))
        return {};
    EGLDeviceEXT devices[kMaxDevices];
    EGLint count = 0;
    if (!eglQueryDevicesEXT(kMaxDevices, devices, &count)) return {};
    return std::vector<EGLDeviceEXT>(devices, devices + count); // not {..}: EGLDeviceEXT is a pointer
}

std::string EglDeviceContext::describeDevice(EGLDeviceEXT device) {
    // Mesa 22.3 has no EGL_EXT_device_query_name (renderer/vendor strings), so the DRM node is the name;
    // the software device has neither and says so through its extension.
    if (hasDeviceExtension(device, "EGL_MESA_device_software")) return "software (EGL_MESA_device_software)";
    if (hasDeviceExtension(device, "EGL_EXT_device_drm_render_node"))
        if (const char* node = deviceString(device, EGL_DRM_RENDER_NODE_FILE_EXT)) return node;
    if (hasDeviceExtension(device, "EGL_EXT_device_drm"))
        if (const char* file = deviceString(device, EGL_DRM_DEVICE_FILE_EXT)) return file;
    return "unnamed EGL device";
}

EglDeviceContext::PickedDevice EglDeviceContext::pickDevice(const ContextOptions& options) {
    if (!epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device"))
        failDevice("EGL client extension EGL_EXT_platform_device missing");
    std::vector<EGLDeviceEXT> devices = enumerateDevices();
    if (devices.empty())
        failDevice("no EGL devices (EGL_EXT_device_enumeration/query missing or none found)");
    int index = options.gpu < 0 ? 0 : options.gpu;
    // An index past the devices this machine has is the user's input, not a missing capability: exit 2,
    // and never a silent fall-back to another backend.
    if (index >= static_cast<int>(devices.size()))
        throw Error("egl-device: --gpu " + std::to_string(options.gpu) +
                        " is out of range: " + std::to_string(devices.size()) + " device(s), indices 0.." +
                        std::to_string(devices.size() - 1),
                    ExitCode::BadInput);
    return {devices[index], index};
}

EGLDisplay EglDeviceContext::openDisplay(EGLDeviceEXT device) {
    return eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
}

} // namespace sb
