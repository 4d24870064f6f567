#include "vk/ComputePipeline.h"

#include <utility>

#include "vk/PipelineLayout.h"
#include "vk/VulkanContext.h"

namespace sb {

ComputePipeline::ComputePipeline(VulkanContext& context, VkShaderModule module,
                                 const std::vector<VkDescriptorSetLayout>& sets, uint32_t pushBytes)
    : mDevice(context.device()), mPushBytes(pushBytes) {
    mLayout = createPipelineLayout(context, sets, pushBytes, VK_SHADER_STAGE_COMPUTE_BIT);
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module;
    info.stage.pName = "main";
    info.layout = mLayout;
    const VkResult r = vkCreateComputePipelines(mDevice, VK_NULL_HANDLE, 1, &info, nullptr, &mPipeline);
    if (r != VK_SUCCESS) release();
    VulkanContext::check(r, "vkCreateComputePipelines");
}

ComputePipeline::~ComputePipeline() {
    release();
}

void ComputePipeline::release() {
    if (!mDevice) return;
    vkDestroyPipeline(mDevice, mPipeline, nullptr);
    vkDestroyPipelineLayout(mDevice, mLayout, nullptr);
    mPipeline = VK_NULL_HANDLE;
    mLayout = VK_NULL_HANDLE;
    mDevice = VK_NULL_HANDLE;
}

ComputePipeline::ComputePipeline(ComputePipeline&& other) noexcept {
    *this = std::move(other);
}

ComputePipeline& ComputePipeline::operator=(ComputePipeline&& other) noexcept {
    if (this == &other) return *this;
    release();
    mDevice = std::exchange(other.mDevice, VK_NULL_HANDLE);
    mLayout = std::exchange(other.mLayout, VK_NULL_HANDLE);
    mPipeline = std::exchange(other.mPipeline, VK_NULL_HANDLE);
    mPushBytes = other.mPushBytes;
    return *this;
}

void ComputePipeline::bind(VkCommandBuffer cmd, const std::vector<VkDescriptorSet>& sets) const {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mPipeline);
    if (!sets.empty())
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mLayout, 0, uint32_t(sets.size()),
                                sets.data(), 0, nullptr);
}

void ComputePipeline::push(VkCommandBuffer cmd, const void* data) const {
    if (mPushBytes) vkCmdPushConstants(cmd, mLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, mPushBytes, data);
}

} // namespace sb
