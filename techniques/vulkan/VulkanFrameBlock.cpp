#include "techniques/vulkan/VulkanFrameBlock.h"

#include <cstring>

#include "core/Error.h"
#include "vk/VulkanContext.h"

namespace sb {

glm::mat4 VulkanFrameBlock::clipFromGl() {
    glm::mat4 m(1.0f);
    m[1][1] = -1.0f;
    m[2][2] = 0.5f;
    m[3][2] = 0.5f;
    return m;
}

glm::mat4 VulkanFrameBlock::depthFromGl() {
    glm::mat4 m(1.0f);
    m[2][2] = 0.5f;
    m[3][2] = 0.5f;
    return m;
}

VulkanFrameBlock::VulkanFrameBlock(VulkanContext& context) : mDevice(context.device()) {
    mStride = context.uniformStride(sizeof(FrameUniformData));
    mBuffer = VulkanBuffer(context, VkDeviceSize(mStride) * kSlots, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);

    // The mesh stage (volume's extrusion=mesh) only where the device has it on: a stage flag of a
    // feature not enabled is invalid.
    const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT |
                                      VK_SHADER_STAGE_FRAGMENT_BIT |
                                      (context.meshShader() ? VK_SHADER_STAGE_MESH_BIT_EXT : 0);
    mSets = DescriptorSets(mDevice,
                           {{DescriptorSets::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, stages)}},
                           "frame block");
    mSets.writeBuffer(0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, mBuffer.buffer(),
                      sizeof(FrameUniformData));
}

VulkanFrameBlock::~VulkanFrameBlock() = default;

uint32_t VulkanFrameBlock::write(const FrameUniformData& data) {
    if (mNext >= kSlots)
        throw Error("vulkan: more than " + std::to_string(kSlots) + " frame blocks in one frame",
                    ExitCode::Failure);
    FrameUniformData d = data;
    d.proj = clipFromGl() * d.proj;
    d.viewProj = clipFromGl() * d.viewProj;
    const uint32_t offset = mNext++ * mStride;
    std::memcpy(static_cast<char*>(mBuffer.map()) + offset, &d, sizeof d);
    return offset;
}

void VulkanFrameBlock::bind(VkCommandBuffer cmd, VkPipelineLayout layout, uint32_t offset) const {
    const VkDescriptorSet set = mSets.set(0);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set, 1, &offset);
}

} // namespace sb
