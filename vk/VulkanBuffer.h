#pragma once
// A VkBuffer with its own memory. Static data (vertices, indices, instances) is device-local and filled
// through a staging copy (create with `data`); per-frame data (uniforms) is host-visible and coherent,
// persistently mapped, written in place (map()). A buffer whose usage includes
// VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT (acceleration-structure inputs and storage, on a device with
// VulkanContext::rayQuery) gets memory allocated for device addresses, and address() says where it is.
#include <cstddef>
#include <cstdint>

#include <vulkan/vulkan.h>

namespace sb {

class VulkanContext;

class VulkanBuffer {
public:
    VulkanBuffer() = default;
    /// Device-local buffer of `size` bytes, filled from `data` through a staging buffer and
    /// VulkanContext::submitNow (usage gets TRANSFER_DST added).
    VulkanBuffer(VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage, const void* data);
    /// Host-visible, coherent, persistently mapped buffer of `size` bytes.
    VulkanBuffer(VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage);
    ~VulkanBuffer();
    VulkanBuffer(VulkanBuffer&& other) noexcept;
    VulkanBuffer& operator=(VulkanBuffer&& other) noexcept;
    VulkanBuffer(const VulkanBuffer&) = delete;
    VulkanBuffer& operator=(const VulkanBuffer&) = delete;

    VkBuffer buffer() const { return mBuffer; }
    VkDeviceSize size() const { return mSize; }
    /// The mapping of a host-visible buffer (nullptr for a device-local one).
    void* map() const { return mMapped; }
    /// The buffer's device address (vkGetBufferDeviceAddress); 0 unless its usage asked for one.
    VkDeviceAddress address() const { return mAddress; }
    explicit operator bool() const { return mBuffer != VK_NULL_HANDLE; }

private:
    void release();
    void allocate(VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage,
                  VkMemoryPropertyFlags flags);
    VkDevice mDevice = VK_NULL_HANDLE;
    VkBuffer mBuffer = VK_NULL_HANDLE;
    VkDeviceMemory mMemory = VK_NULL_HANDLE;
    VkDeviceSize mSize = 0;
    void* mMapped = nullptr;
    VkDeviceAddress mAddress = 0;
};

} // namespace sb
