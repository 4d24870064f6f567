#include "vk/VulkanBuffer.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include "vk/VulkanContext.h"

namespace sb {

VulkanBuffer::VulkanBuffer(VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage,
                           const void* data) {
    allocate(context, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (!data || size == 0) return;
    VulkanBuffer staging(context, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    std::memcpy(staging.map(), data, static_cast<size_t>(size));
    context.submitNow([&](VkCommandBuffer cmd) {
        VkBufferCopy region{0, 0, size};
        vkCmdCopyBuffer(cmd, staging.buffer(), mBuffer, 1, &region);
    });
}

VulkanBuffer::VulkanBuffer(VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage) {
    allocate(context, size, usage,
             VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    VulkanContext::check(vkMapMemory(mDevice, mMemory, 0, VK_WHOLE_SIZE, 0, &mMapped), "vkMapMemory");
}

void VulkanBuffer::allocate(VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage,
                            VkMemoryPropertyFlags flags) {
    mDevice = context.device();
    mSize = size;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = std::max<VkDeviceSize>(size, 4); // a zero-size buffer is invalid
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VulkanContext::check(vkCreateBuffer(mDevice, &info, nullptr, &mBuffer), "vkCreateBuffer");
    try {
        VkMemoryRequirements req{};
        vkGetBufferMemoryRequirements(mDevice, mBuffer, &req);
        const bool addressed = (usage & VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT) != 0;
        VkMemoryAllocateFlagsInfo addressFlags{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_FLAGS_INFO};
        addressFlags.flags = VK_MEMORY_ALLOCATE_DEVICE_ADDRESS_BIT;
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.pNext = addressed ? &addressFlags : nullptr;
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex = context.memoryType(req.memoryTypeBits, flags);
        VulkanContext::check(vkAllocateMemory(mDevice, &alloc, nullptr, &mMemory), "vkAllocateMemory");
        VulkanContext::check(vkBindBufferMemory(mDevice, mBuffer, mMemory, 0), "vkBindBufferMemory");
        if (addressed) {
            VkBufferDeviceAddressInfo where{VK_STRUCTURE_TYPE_BUFFER_DEVICE_ADDRESS_INFO};
            where.buffer = mBuffer;
            mAddress = vkGetBufferDeviceAddress(mDevice, &where);
        }
    } catch (...) {
        release();
        throw;
    }
}

VulkanBuffer::~VulkanBuffer() {
    release();
}

void VulkanBuffer::release() {
    if (mDevice) {
        if (mMapped) vkUnmapMemory(mDevice, mMemory);
        if (mBuffer) vkDestroyBuffer(mDevice, mBuffer, nullptr);
        if (mMemory) vkFreeMemory(mDevice, mMemory, nullptr);
    }
    mDevice = VK_NULL_HANDLE;
    mBuffer = VK_NULL_HANDLE;
    mMemory = VK_NULL_HANDLE;
    mMapped = nullptr;
    mSize = 0;
    mAddress = 0;
}

VulkanBuffer::VulkanBuffer(VulkanBuffer&& other) noexcept
    : mDevice(std::exchange(other.mDevice, VK_NULL_HANDLE)),
      mBuffer(std::exchange(other.mBuffer, VK_NULL_HANDLE)),
      mMemory(std::exchange(other.mMemory, VK_NULL_HANDLE)), mSize(std::exchange(other.mSize, 0)),
      mMapped(std::exchange(other.mMapped, nullptr)), mAddress(std::exchange(other.mAddress, 0)) {}

VulkanBuffer& VulkanBuffer::operator=(VulkanBuffer&& other) noexcept {
    if (this != &other) {
        release();
        mDevice = std::exchange(other.mDevice, VK_NULL_HANDLE);
        mBuffer = std::exchange(other.mBuffer, VK_NULL_HANDLE);
        mMemory = std::exchange(other.mMemory, VK_NULL_HANDLE);
        mSize = std::exchange(other.mSize, 0);
        mMapped = std::exchange(other.mMapped, nullptr);
        mAddress = std::exchange(other.mAddress, 0);
    }
    return *this;
}

} // namespace sb
