#pragma once
// Slots of a dynamic uniform buffer: `count` slots of `bytes` each at VulkanContext::uniformStride, in
// one host-visible buffer cleared to zero; a pass binds its slot's offset (a light's matrix, a
// cascade's, a cube's faces) with the descriptor set whose binding covers `bytes`.
#include <cstddef>
#include <cstdint>

#include "vk/VulkanBuffer.h"

namespace sb {

class UniformSlots {
public:
    UniformSlots() = default;
    UniformSlots(VulkanContext& context, VkDeviceSize bytes, uint32_t count);

    VkBuffer buffer() const { return mBuffer.buffer(); }
    VkDeviceSize bytes() const { return mBytes; } ///< one slot's range (the descriptor's)
    uint32_t stride() const { return mStride; }
    uint32_t offset(size_t slot) const { return mStride * uint32_t(slot); } ///< the dynamic offset
    /// Where slot `slot` is mapped (nullptr before creation). The caller writes at most bytes().
    char* at(size_t slot) const;
    /// Writes `size` bytes of `data` at the start of slot `slot`.
    void write(size_t slot, const void* data, size_t size) const;
    /// Binds `set` (set number 1 of `layout`, the pass's own) at slot `slot`'s offset.
    void bind(VkCommandBuffer cmd, VkPipelineLayout layout, VkDescriptorSet set, size_t slot) const;

private:
    VulkanBuffer mBuffer;
    VkDeviceSize mBytes = 0;
    uint32_t mStride = 0;
};

} // namespace sb
