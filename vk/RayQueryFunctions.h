#pragma once
// The entry points of VK_KHR_acceleration_structure, which the Vulkan loader does not export (extension
// commands are fetched from the device), and the device extensions ray queries need. VulkanContext
// loads them when it enables ray queries (VulkanContext::rayQuery); techniques/raytraced/ calls them.
#include <array>

#include <vulkan/vulkan.h>

namespace sb {

/// What a device must offer for ray queries from a shader: the query itself, the structures it
/// traverses, and the deferred host operations that VK_KHR_acceleration_structure requires.
inline constexpr std::array<const char*, 3> kRayQueryExtensions = {
    VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME, VK_KHR_RAY_QUERY_EXTENSION_NAME,
    VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME};

struct RayQueryFunctions {
    PFN_vkCreateAccelerationStructureKHR createAccelerationStructure = nullptr;
    PFN_vkDestroyAccelerationStructureKHR destroyAccelerationStructure = nullptr;
    PFN_vkGetAccelerationStructureBuildSizesKHR getBuildSizes = nullptr;
    PFN_vkCmdBuildAccelerationStructuresKHR cmdBuild = nullptr;
    PFN_vkGetAccelerationStructureDeviceAddressKHR getDeviceAddress = nullptr;

    /// Every pointer from `device`; throws sb::Error(Failure) naming the first the device does not return.
    static RayQueryFunctions load(VkDevice device);
};

} // namespace sb
