#pragma once
// One compute pipeline with its layout: a compute shader's module, the descriptor set layouts it reads
// (set 0 onwards) and one push-constant block seen by the compute stage. What volume's extrusion=compute
// dispatches on Vulkan, and what the Vulkan tests' compute fixture (tests/VkComputeKernel.h) runs GLSL
// pieces with.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

namespace sb {

class VulkanContext;

class ComputePipeline {
public:
    ComputePipeline() = default;
    /// Creates the layout (`sets`, `pushBytes` of push constants; 0: none) and the pipeline of `module`
    /// (entry point main). Throws sb::Error(Failure) naming the VkResult. The module stays the caller's.
    ComputePipeline(VulkanContext& context, VkShaderModule module,
                    const std::vector<VkDescriptorSetLayout>& sets, uint32_t pushBytes);
    ~ComputePipeline();
    ComputePipeline(ComputePipeline&& other) noexcept;
    ComputePipeline& operator=(ComputePipeline&& other) noexcept;
    ComputePipeline(const ComputePipeline&) = delete;
    ComputePipeline& operator=(const ComputePipeline&) = delete;

    VkPipeline pipeline() const { return mPipeline; }
    VkPipelineLayout layout() const { return mLayout; }
    explicit operator bool() const { return mPipeline != VK_NULL_HANDLE; }

    /// Binds the pipeline and `sets` as sets 0, 1, ... for the dispatches that follow.
    void bind(VkCommandBuffer cmd, const std::vector<VkDescriptorSet>& sets) const;
    /// Pushes the whole block (`pushBytes` of `data`).
    void push(VkCommandBuffer cmd, const void* data) const;

private:
    void release();
    VkDevice mDevice = VK_NULL_HANDLE;
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    VkPipeline mPipeline = VK_NULL_HANDLE;
    uint32_t mPushBytes = 0;
};

} // namespace sb
