#include "vk/UniformSlots.h"

#include <cstring>

#include "vk/VulkanContext.h"

namespace sb {

UniformSlots::UniformSlots(VulkanContext& context, VkDeviceSize bytes, uint32_t count)
    : mBytes(bytes), mStride(context.uniformStride(bytes)) {
    mBuffer = VulkanBuffer(context, VkDeviceSize(mStride) * count, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memset(mBuffer.map(), 0, size_t(mStride) * count);
}

char* UniformSlots::at(size_t slot) const {
    char* base = static_cast<char*>(mBuffer.map());
    return base ? base + size_t(mStride) * slot : nullptr;
}

void UniformSlots::write(size_t slot, const void* data, size_t size) const {
    std::memcpy(at(slot), data, size);
}

void UniformSlots::bind(VkCommandBuffer cmd, VkPipelineLayout layout, VkDescriptorSet set,
                        size_t slot) const {
    const uint32_t dynamicOffset = offset(slot);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 1, 1, &set, 1, &dynamicOffset);
}

} // namespace sb
