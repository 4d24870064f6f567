#pragma once
// A compute fixture of the Vulkan tests: one compute shader of the source tree (compiled from the root,
// so that it may include the shaders the techniques compile, not copies), storage buffers at bindings
// 0..n-1 of set 0 and one push-constant block, dispatched with its results made visible to the host.
// The tests that check a GLSL piece on lavapipe against an answer computed on the CPU use it.
#include <cstdint>
#include <string>
#include <vector>

#include "TestPaths.h"
#include "vk/DescriptorSets.h"
#include "vk/ShaderModuleCache.h"
#include "vk/VulkanBuffer.h"
#include "vk/VulkanContext.h"

namespace sb::test {

class ComputeKernel {
public:
    /// Compiles `shader` (a path from `root`, by default the source tree's root) with `defines`, for
    /// `buffers` storage buffers and a push block of `pushBytes` (0: none). `label` names the descriptor
    /// sets in errors. A fixture whose includes are written from shaders/ (as the techniques' shaders
    /// include each other) passes a root holding links to the folders it needs.
    ComputeKernel(VulkanContext& context, const std::string& shader, const Defines& defines, uint32_t buffers,
                  uint32_t pushBytes, const char* label, const std::string& root = SB_SOURCE_DIR)
        : mContext(context), mCache(context, root), mSets(context.device(), {bindings(buffers)}, label),
          mPushBytes(pushBytes) {
        const VkShaderModule module = mCache.get(shader, defines, ShaderStage::Compute);
        const VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes};
        const VkDescriptorSetLayout setLayout = mSets.layout(0);
        VkPipelineLayoutCreateInfo layout{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        layout.setLayoutCount = 1;
        layout.pSetLayouts = &setLayout;
        layout.pushConstantRangeCount = pushBytes ? 1u : 0u;
        layout.pPushConstantRanges = &range;
        VulkanContext::check(vkCreatePipelineLayout(context.device(), &layout, nullptr, &mLayout),
                             "vkCreatePipelineLayout");
        VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
        info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
        info.stage.module = module;
        info.stage.pName = "main";
        info.layout = mLayout;
        VulkanContext::check(
            vkCreateComputePipelines(context.device(), VK_NULL_HANDLE, 1, &info, nullptr, &mPipeline),
            "vkCreateComputePipelines");
    }
    ~ComputeKernel() {
        vkDestroyPipeline(mContext.device(), mPipeline, nullptr);
        vkDestroyPipelineLayout(mContext.device(), mLayout, nullptr);
    }
    ComputeKernel(const ComputeKernel&) = delete;
    ComputeKernel& operator=(const ComputeKernel&) = delete;

    /// Binds `buffers` (binding i: buffers[i], whole) and `push` (pushBytes of it), dispatches `groups`
    /// work groups along x and waits; the shader's writes are then visible through the buffers' maps.
    void dispatch(const std::vector<const VulkanBuffer*>& buffers, const void* push, uint32_t groups) {
        for (uint32_t i = 0; i < buffers.size(); ++i)
            mSets.writeBuffer(0, i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers[i]->buffer(),
                              buffers[i]->size());
        mContext.submitNow([&](VkCommandBuffer cmd) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mPipeline);
            const VkDescriptorSet set = mSets.set(0);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mLayout, 0, 1, &set, 0, nullptr);
            if (mPushBytes)
                vkCmdPushConstants(cmd, mLayout, VK_SHADER_STAGE_COMPUTE_BIT, 0, mPushBytes, push);
            vkCmdDispatch(cmd, groups, 1, 1);
            VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
            toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
            toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
            vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                                 &toHost, 0, nullptr, 0, nullptr);
        });
    }

private:
    static DescriptorSets::Bindings bindings(uint32_t buffers) {
        DescriptorSets::Bindings out;
        for (uint32_t i = 0; i < buffers; ++i)
            out.push_back(
                DescriptorSets::binding(i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT));
        return out;
    }

    VulkanContext& mContext;
    ShaderModuleCache mCache; ///< rooted at the source tree
    DescriptorSets mSets;
    uint32_t mPushBytes = 0;
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    VkPipeline mPipeline = VK_NULL_HANDLE;
};

} // namespace sb::test
