#include "techniques/proxy/ProxyVulkan.h"

#include <cstring>

#include "techniques/proxy/Proxy.h"

namespace sb {

ProxyVulkan::ProxyVulkan() : VulkanTechnique(Proxy::declaration()) {}

ProxyVulkan::~ProxyVulkan() {
    release();
}

void ProxyVulkan::release() {
    if (!mDevice) return;
    vkDestroyPipelineLayout(mDevice, mLayout, nullptr);
    mLayout = VK_NULL_HANDLE;
    mSets = DescriptorSets();
    mBlock = VulkanBuffer();
    mProxies = VulkanBuffer();
    mIndexMap = VulkanBuffer();
}

void ProxyVulkan::setScene(const Scene& scene) {
    mPlan.setScene(scene, properties());
}

void ProxyVulkan::createBuffers(VulkanContext& context) {
    // The largest frame's sizes: every proxy in view, every cell of the grid full. Written in place.
    const VkDeviceSize records = mPlan.maxInView() * sizeof(ProxyPlan::GpuProxy);
    const VkDeviceSize entries = mPlan.indexEntries(properties()) * sizeof(uint32_t);
    mBlock = VulkanBuffer(context, sizeof(ProxyPlan::Uniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    mProxies = VulkanBuffer(context, records, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    mIndexMap = VulkanBuffer(context, entries, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    std::memset(mProxies.map(), 0, records);
    std::memset(mIndexMap.map(), 0, entries);
    using D = DescriptorSets;
    constexpr VkShaderStageFlags kFragment = VK_SHADER_STAGE_FRAGMENT_BIT;
    mSets = DescriptorSets(mDevice,
                           {{D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kFragment),
                             D::binding(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kFragment),
                             D::binding(2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kFragment)}},
                           "proxy");
    mSets.writeBuffer(0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, mBlock.buffer(), sizeof(ProxyPlan::Uniforms));
    mSets.writeBuffer(0, 1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mProxies.buffer(), records);
    mSets.writeBuffer(0, 2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mIndexMap.buffer(), entries);
}

void ProxyVulkan::compile(const VulkanCompileContext& ctx) {
    release();
    mDevice = ctx.context.device();
    createBuffers(ctx.context);
    mLayout = createScenePipelineLayout(ctx, {mSets.layout(0)});
    const Defines defines = mPlan.defines(ctx.defines(), properties());
    std::string key = "proxy-lighting|";
    GraphicsPipelineDesc desc =
        scenePipeline(ctx, "common/scene.vert", "proxy/lit.frag", defines, mLayout, key);
    mPipeline.build(ctx.pipelines, key, desc, ctx.targets);
    setPermutationKey(definesKey(defines));
}

void ProxyVulkan::uploadFrame(VulkanFrameContext& ctx) {
    mPlan.build(ctx.proj * ctx.view, properties());
    const std::vector<ProxyPlan::GpuProxy>& inView = mPlan.inView();
    if (!inView.empty())
        std::memcpy(mProxies.map(), inView.data(), inView.size() * sizeof(ProxyPlan::GpuProxy));
    if (mPlan.useGrid()) {
        const std::vector<uint32_t>& texels = mPlan.grid().texels();
        std::memcpy(mIndexMap.map(), texels.data(), texels.size() * sizeof(uint32_t));
    }
    const ProxyPlan::Uniforms u = mPlan.uniforms(properties(), ctx.targets.width(), ctx.targets.height());
    std::memcpy(mBlock.map(), &u, sizeof u);
}

void ProxyVulkan::execute(VulkanFrameContext& ctx) {
    ctx.submitter.resetStats();
    ctx.passes.begin("index_map");
    uploadFrame(ctx);
    ctx.passes.begin("lighting");
    drawLitScene(ctx, mPipeline, mLayout, mSets.set(0));
    mCounters = mPlan.counters(ctx.submitter.stats());
}

} // namespace sb
