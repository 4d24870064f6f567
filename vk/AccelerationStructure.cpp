#include "vk/AccelerationStructure.h"

#include <utility>

#include "vk/VulkanContext.h"

namespace sb {

AccelerationStructure::AccelerationStructure(VulkanContext& context, VkAccelerationStructureTypeKHR type,
                                             VkDeviceSize bytes)
    : mContext(&context), mStorage(context, bytes,
                                   VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_STORAGE_BIT_KHR |
                                       VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT,
                                   nullptr) {
    const RayQueryFunctions& f = context.rayQueryFunctions();
    VkAccelerationStructureCreateInfoKHR info{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_CREATE_INFO_KHR};
    info.buffer = mStorage.buffer();
    info.size = bytes;
    info.type = type;
    VulkanContext::check(f.createAccelerationStructure(context.device(), &info, nullptr, &mHandle),
                         "vkCreateAccelerationStructureKHR");
    VkAccelerationStructureDeviceAddressInfoKHR where{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_DEVICE_ADDRESS_INFO_KHR};
    where.accelerationStructure = mHandle;
    mAddress = f.getDeviceAddress(context.device(), &where);
}

AccelerationStructure::~AccelerationStructure() {
    release();
}

void AccelerationStructure::release() {
    if (mHandle)
        mContext->rayQueryFunctions().destroyAccelerationStructure(mContext->device(), mHandle, nullptr);
    mHandle = VK_NULL_HANDLE;
    mAddress = 0;
    mStorage = VulkanBuffer();
}

AccelerationStructure::AccelerationStructure(AccelerationStructure&& other) noexcept {
    *this = std::move(other);
}

AccelerationStructure& AccelerationStructure::operator=(AccelerationStructure&& other) noexcept {
    if (this == &other) return *this;
    release();
    mContext = other.mContext;
    mStorage = std::move(other.mStorage);
    mHandle = std::exchange(other.mHandle, VK_NULL_HANDLE);
    mAddress = std::exchange(other.mAddress, 0);
    return *this;
}

} // namespace sb
