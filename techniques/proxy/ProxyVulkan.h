#pragma once
// `proxy` on Vulkan: ProxyGL's two passes with the same declaration, properties, proxies, CPU IndexMap
// and shader (common/scene.vert, shaders/proxy/lit.frag and its `#ifdef VULKAN` block), recorded into the
// frame's command buffer. What both forms share is ProxyPlan (techniques/proxy/ProxyPlan.h).
//
// index_map: the CPU builds the grid (ProxyPlan::build) and writes the records of the proxies in view and
// the IndexMap into two host-visible storage buffers (GL's two shader storage buffers), sized in
// compile() for the largest frame (every proxy in view, every cell full), so a frame allocates nothing
// and writes no descriptor. lighting: the scene drawn once with set 1 = the uniforms GL sets by location
// (ProxyBlock, with the viewport's height to turn gl_FragCoord's y into GL's lower-left origin) and the
// two buffers.
#include "techniques/proxy/ProxyPlan.h"
#include "techniques/vulkan/ScenePass.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"

namespace sb {

class ProxyVulkan final : public VulkanTechnique {
public:
    ProxyVulkan();
    ~ProxyVulkan() override;
    void setScene(const Scene& scene) override;
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }

private:
    void release();
    void createBuffers(VulkanContext& context);
    void uploadFrame(VulkanFrameContext& ctx);

    ProxyPlan mPlan;
    VkDevice mDevice = VK_NULL_HANDLE;
    VulkanBuffer mBlock, mProxies, mIndexMap; ///< ProxyBlock, ProxyParams, ProxyIndexMap
    DescriptorSets mSets;
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    ScenePipeline mPipeline;
    Counters mCounters;
};

} // namespace sb
