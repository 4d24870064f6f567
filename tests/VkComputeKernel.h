#pragma once
// A compute fixture of the Vulkan tests: one compute shader of the source tree (compiled from the root,
// so that it may include the shaders the techniques compile, not copies), storage buffers at bindings
// 0..n-1 of set 0 and one push-constant block (vk/ComputePipeline.h), dispatched with its results made
// visible to the host. The tests that check a GLSL piece on lavapipe against an answer computed on the CPU
// use it.
#include <cstdint>
#include <string>
#include <vector>

#include "TestPaths.h"
#include "vk/ComputePipeline.h"
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
          mPipeline(context, mCache.get(shader, defines, ShaderStage::Compute), {mSets.layout(0)},
                    pushBytes) {}
    ComputeKernel(const ComputeKernel&) = delete;
    ComputeKernel& operator=(const ComputeKernel&) = delete;

    /// Binds `buffers` (binding i: buffers[i], whole) and `push` (pushBytes of it), dispatches `groups`
    /// work groups along x and waits; the shader's writes are then visible through the buffers' maps.
    void dispatch(const std::vector<const VulkanBuffer*>& buffers, const void* push, uint32_t groups) {
        for (uint32_t i = 0; i < buffers.size(); ++i)
            mSets.writeBuffer(0, i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers[i]->buffer(),
                              buffers[i]->size());
        mContext.submitNow([&](VkCommandBuffer cmd) {
            mPipeline.bind(cmd, {mSets.set(0)});
            mPipeline.push(cmd, push);
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
    ComputePipeline mPipeline;
};

} // namespace sb::test
