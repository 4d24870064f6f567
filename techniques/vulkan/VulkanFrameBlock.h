#pragma once
// The per-frame uniform block on Vulkan (techniques/gl/FrameUniforms.h on GL; the same std140 layout,
// shaders/common/frame.glsl): set 0, binding 0, a dynamic uniform buffer with a few slots per frame, so a
// technique that draws with a projection of its own (volume's infinite far plane) writes one more slot
// and binds it at another offset within the same command buffer. Host-visible and written in place: the
// harness waits for each frame's fence before the next is recorded, so no slot is in flight when
// written.
//
// Clip space. The frame's matrices are GL's (glm, y up, z in [-w, w]); the block holds them times
// clipFromGl(): y flipped and z mapped to [0, w], so the same camera gives the same pixels and the same
// window depths on both APIs (VulkanTargets reads rows back bottom-up, as glReadPixels does).
#include <cstdint>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "techniques/FrameBlock.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"

namespace sb {

class VulkanContext;

class VulkanFrameBlock {
public:
    static constexpr uint32_t kSlots = 8;
    explicit VulkanFrameBlock(VulkanContext& context);
    ~VulkanFrameBlock();
    VulkanFrameBlock(const VulkanFrameBlock&) = delete;
    VulkanFrameBlock& operator=(const VulkanFrameBlock&) = delete;

    /// Vulkan's clip space from GL's: y flipped (the window's rows run the other way) and z from
    /// [-w, w] to [0, w]. For passes into the frame targets.
    static glm::mat4 clipFromGl();
    /// z only, for offscreen maps that are sampled, not shown: texture v and window y both start at
    /// NDC y = -1 on both APIs, so a map needs no flip to be read with GL's shadow matrices.
    static glm::mat4 depthFromGl();

    /// The frame starts again at slot 0.
    void beginFrame() { mNext = 0; }
    /// Writes `data` (GL matrices: proj and viewProj are converted here) into the next slot and
    /// returns its dynamic offset. Throws sb::Error(Failure) past kSlots.
    uint32_t write(const FrameUniformData& data);
    /// Binds slot `offset` as set 0 of `layout`.
    void bind(VkCommandBuffer cmd, VkPipelineLayout layout, uint32_t offset) const;
    /// The set layout every pipeline of a technique puts first.
    VkDescriptorSetLayout setLayout() const { return mSets.layout(0); }

private:
    VkDevice mDevice;
    VulkanBuffer mBuffer;
    uint32_t mStride = 0, mNext = 0;
    DescriptorSets mSets;
};

} // namespace sb
