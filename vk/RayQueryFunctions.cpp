#include "vk/RayQueryFunctions.h"

#include <string>

#include "core/Error.h"

namespace sb {
namespace {

template <typename T>
T fetch(VkDevice device, const char* name) {
    auto f = reinterpret_cast<T>(vkGetDeviceProcAddr(device, name));
    if (!f) throw Error(std::string("vulkan: vkGetDeviceProcAddr returned no ") + name, ExitCode::Failure);
    return f;
}

} // namespace

RayQueryFunctions RayQueryFunctions::load(VkDevice device) {
    RayQueryFunctions f;
    f.createAccelerationStructure =
        fetch<PFN_vkCreateAccelerationStructureKHR>(device, "vkCreateAccelerationStructureKHR");
    f.destroyAccelerationStructure =
        fetch<PFN_vkDestroyAccelerationStructureKHR>(device, "vkDestroyAccelerationStructureKHR");
    f.getBuildSizes =
        fetch<PFN_vkGetAccelerationStructureBuildSizesKHR>(device, "vkGetAccelerationStructureBuildSizesKHR");
    f.cmdBuild =
        fetch<PFN_vkCmdBuildAccelerationStructuresKHR>(device, "vkCmdBuildAccelerationStructuresKHR");
    f.getDeviceAddress = fetch<PFN_vkGetAccelerationStructureDeviceAddressKHR>(
        device, "vkGetAccelerationStructureDeviceAddressKHR");
    return f;
}

} // namespace sb
