#pragma once
// One acceleration structure (VK_KHR_acceleration_structure) with the buffer that stores it, owned
// together and destroyed together, as VulkanBuffer owns a buffer and its memory. Scene-agnostic: what
// goes into it (a mesh's triangles, a scene's instances) is techniques/raytraced/AccelerationStructures.h's.
// Only on a device with VulkanContext::rayQuery().
#include <vulkan/vulkan.h>

#include "vk/VulkanBuffer.h"

namespace sb {

class VulkanContext;

class AccelerationStructure {
public:
    AccelerationStructure() = default;
    /// A structure of `type` over `bytes` of device-local storage (the size
    /// vkGetAccelerationStructureBuildSizesKHR gave). Throws sb::Error(Failure) when creation fails.
    AccelerationStructure(VulkanContext& context, VkAccelerationStructureTypeKHR type, VkDeviceSize bytes);
    ~AccelerationStructure();
    AccelerationStructure(AccelerationStructure&& other) noexcept;
    AccelerationStructure& operator=(AccelerationStructure&& other) noexcept;
    AccelerationStructure(const AccelerationStructure&) = delete;
    AccelerationStructure& operator=(const AccelerationStructure&) = delete;

    VkAccelerationStructureKHR handle() const { return mHandle; }
    /// Where a top level's instances point at it (vkGetAccelerationStructureDeviceAddressKHR).
    VkDeviceAddress address() const { return mAddress; }
    /// The bytes of its storage.
    VkDeviceSize bytes() const { return mStorage.size(); }
    explicit operator bool() const { return mHandle != VK_NULL_HANDLE; }

private:
    void release();
    const VulkanContext* mContext = nullptr;
    VulkanBuffer mStorage;
    VkAccelerationStructureKHR mHandle = VK_NULL_HANDLE;
    VkDeviceAddress mAddress = 0;
};

} // namespace sb
