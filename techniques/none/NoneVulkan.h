#pragma once
// `none` on Vulkan (techniques/vulkan/VulkanTechnique.h): the same one lit pass as NoneGL, the
// same shaders (common/scene.vert, common/lit.frag), recorded into the frame's command buffer.
#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

class NoneVulkan final : public VulkanTechnique {
public:
    NoneVulkan();
    ~NoneVulkan() override;
    void setScene(const Scene&) override {}
    void sceneChanged(const Scene&, uint32_t) override {}
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }

private:
    VkDevice mDevice = VK_NULL_HANDLE;
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    ScenePipeline mPipeline;
    Counters mCounters;
};

} // namespace sb
