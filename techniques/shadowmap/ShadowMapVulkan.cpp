#include "techniques/shadowmap/ShadowMapVulkan.h"

#include <algorithm>
#include <cstring>

#include "core/Error.h"
#include "scenes/ShadowWork.h"
#include "techniques/shadowmap/DepthLightingFrame.h"
#include "techniques/shadowmap/ShadowMap.h"
#include "techniques/shadowmap/ShadowMapProperties.h"
#include "techniques/shadowmap/VulkanDepthMaps.h"
#include "techniques/vulkan/ScenePass.h"

namespace sb {

namespace {
using P = ShadowMapProperties;

/// std140 offsets of shadowmap/lighting.frag's ShadowMapBlock for `lights` lights.
struct BlockLayout {
    explicit BlockLayout(uint32_t lights)
        : texelWorld(64 * lights), normalOffset(80 * lights), kernelTaps(normalOffset + 4),
          targetHeight(normalOffset + 8), kernel(normalOffset + 16), size(kernel + 64 * 16) {}
    uint32_t texelWorld, normalOffset, kernelTaps, targetHeight, kernel, size;
};

} // namespace

ShadowMapVulkan::ShadowMapVulkan() : VulkanTechnique(ShadowMap::declaration()) {}

ShadowMapVulkan::~ShadowMapVulkan() {
    release();
}

void ShadowMapVulkan::release() {
    if (!mDevice) return;
    for (VkFramebuffer f : mFramebuffers) vkDestroyFramebuffer(mDevice, f, nullptr);
    mFramebuffers.clear();
    vkDestroyRenderPass(mDevice, mDepthPass, nullptr);
    vkDestroySampler(mDevice, mSampler, nullptr);
    vkDestroyPipelineLayout(mDevice, mDepthLayout, nullptr);
    vkDestroyPipelineLayout(mDevice, mLightingLayout, nullptr);
    mDepthPass = VK_NULL_HANDLE;
    mSampler = VK_NULL_HANDLE;
    mSets = DescriptorSets();
    mDepthLayout = mLightingLayout = VK_NULL_HANDLE;
    mMaps = VulkanImage();
}

void ShadowMapVulkan::setScene(const Scene& scene) {
    mLights.setScene(scene, "shadowmap");
    mCulling.setScene(scene);
}

void ShadowMapVulkan::sceneChanged(const Scene& scene, uint32_t) {
    setScene(scene);
    fitTexels(scene);
    writeLightingBlock(-1.0f);
}

void ShadowMapVulkan::fitTexels(const Scene& scene) {
    const PropertySet& p = properties();
    const double kernel = mKernel.empty() ? double(p.getInt(P::kPcf)) : p.getFloat("radius");
    ShadowMap::fitTexels(scene, mLights, mSize, kernel, mNormalOffset, mTexelWorld, mView);
}

void ShadowMapVulkan::createMaps(VulkanContext& context, int size, int layers) {
    const VkFormat format = VulkanDepthMaps::format(context.physicalDevice());
    mMaps = VulkanDepthMaps::image(context, format, uint32_t(size), uint32_t(layers), false);
    mDepthPass = VulkanDepthMaps::renderPass(mDevice, format);
    for (int i = 0; i < layers; ++i)
        mFramebuffers.push_back(
            VulkanDepthMaps::framebuffer(mDevice, mDepthPass, mMaps.layerView(uint32_t(i)), uint32_t(size)));
}

void ShadowMapVulkan::createDescriptors(VulkanContext& context) {
    mSampler = VulkanDepthMaps::sampler(mDevice, properties().getBool("hardware_compare"));
    // Set 1 of the depth pass: the light's matrix, one dynamic slot per light (LightPass). Set 1 of the
    // lighting pass: ShadowMapBlock and the map.
    using D = DescriptorSets;
    mSets = DescriptorSets(
        mDevice,
        {{D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, VK_SHADER_STAGE_VERTEX_BIT)},
         {D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                     VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT),
          D::binding(1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)}},
        "shadowmap");
    const VkDeviceSize align = context.properties().limits.minUniformBufferOffsetAlignment;
    mLightStride = uint32_t((sizeof(glm::mat4) + align - 1) / align * align);
    mLightPass = VulkanBuffer(context, VkDeviceSize(mLightStride) * uint32_t(mLayers),
                              VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    const BlockLayout block{uint32_t(mLayers)};
    mLightingBlock = VulkanBuffer(context, block.size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memset(mLightingBlock.map(), 0, block.size);
    mSets.writeBuffer(kDepthSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, mLightPass.buffer(),
                      sizeof(glm::mat4));
    mSets.writeBuffer(kLightingSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, mLightingBlock.buffer(),
                      block.size);
    mSets.writeImage(kLightingSet, 1, mSampler, mMaps.view(),
                     VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
}

void ShadowMapVulkan::writeLightingBlock(float targetHeight) {
    char* base = static_cast<char*>(mLightingBlock.map());
    if (!base) return;
    const BlockLayout block{uint32_t(mLayers)};
    const auto& shadow = mLights.shadowMatrices();
    for (size_t i = 0; i < shadow.size() && i < size_t(mLayers); ++i)
        std::memcpy(base + 64 * i, &shadow[i], sizeof(glm::mat4));
    for (size_t i = 0; i < mTexelWorld.size() && i < size_t(mLayers); ++i)
        std::memcpy(base + block.texelWorld + 16 * i, &mTexelWorld[i], sizeof(float));
    std::memcpy(base + block.normalOffset, &mNormalOffset, sizeof(float));
    const int32_t taps = int32_t(mKernel.size());
    std::memcpy(base + block.kernelTaps, &taps, sizeof taps);
    if (targetHeight >= 0.0f) std::memcpy(base + block.targetHeight, &targetHeight, sizeof(float));
    for (size_t k = 0; k < mKernel.size() && k < 64; ++k)
        std::memcpy(base + block.kernel + 16 * k, &mKernel[k], sizeof(glm::vec2));
    // The depth pass's light matrices: Vulkan's depth range, no flip (VulkanFrameBlock::depthFromGl).
    char* lights = static_cast<char*>(mLightPass.map());
    for (size_t i = 0; i < mLights.viewProj().size() && i < size_t(mLayers); ++i) {
        const glm::mat4 m = VulkanFrameBlock::depthFromGl() * mLights.viewProj()[i];
        std::memcpy(lights + mLightStride * i, &m, sizeof m);
    }
}

void ShadowMapVulkan::compile(const VulkanCompileContext& ctx) {
    release();
    mDevice = ctx.context.device();
    const PropertySet& p = properties();
    mLayers = std::max<int>(1, int(mLights.size()));
    mSize = int(p.getInt(P::kResolution));
    createMaps(ctx.context, mSize, mLayers);
    createDescriptors(ctx.context);

    // Depth pass: casters only, depth with the bias of glPolygonOffset(slope, constant), no colour.
    mDepthLayout = createScenePipelineLayout(ctx, {mSets.layout(kDepthSet)});
    const Defines base = ctx.submitter.defines();
    std::string depthKey = "shadowmap-depth|bias=" + std::to_string(p.getFloat(P::kBiasSlope)) + "," +
                           std::to_string(p.getFloat(P::kBiasConstant)) + "|";
    GraphicsPipelineDesc depth =
        scenePipeline(ctx, "shadowmap/depth.vert", "shadowmap/depth.frag", base, mDepthLayout, depthKey);
    depth.depthBias = true;
    depth.depthBiasSlope = float(p.getFloat(P::kBiasSlope));
    depth.depthBiasConstant = float(p.getFloat(P::kBiasConstant));
    depth.colourAttachments = 0;
    depth.renderPass = mDepthPass;
    mDepthPipeline = ctx.pipelines.get(depthKey, depth);

    // Lighting pass: the declaration's defines, the GL form's permutation for permutation.
    const Defines lit = ShadowMap::lightingDefines(ctx.defines(), p, mLayers);
    mKernel = ShadowMap::kernelOffsets(p);
    mNormalOffset = float(p.getFloat(ShadowMap::kNormalOffset));
    mCull = p.getBool(ShadowMap::kCull);
    fitTexels(ctx.scene);
    writeLightingBlock(float(ctx.targets.height()));
    mLightingLayout = createScenePipelineLayout(ctx, {mSets.layout(kLightingSet)});
    std::string litKey = "shadowmap-lighting|";
    GraphicsPipelineDesc lighting =
        scenePipeline(ctx, "common/scene.vert", "shadowmap/lighting.frag", lit, mLightingLayout, litKey);
    mLightingPipeline.build(ctx.pipelines, litKey, lighting, ctx.targets);
    setPermutationKey(definesKey(base) + "|" + definesKey(lit));
}

void ShadowMapVulkan::renderDepth(VulkanFrameContext& ctx) {
    mCulled = 0;
    mView.reach.camera = ctx.proj * ctx.view;
    VkClearValue clear{};
    clear.depthStencil = {1.0f, 0};
    for (size_t i = 0; i < mLights.viewProj().size(); ++i) {
        if (!mLights.castsShadow(i)) continue;
        mCulled += mLights.cullCasters(i, mCulling, mKeep, mCull ? &mView : nullptr);
        VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        begin.renderPass = mDepthPass;
        begin.framebuffer = mFramebuffers[i];
        begin.renderArea.extent = {uint32_t(mSize), uint32_t(mSize)};
        begin.clearValueCount = 1;
        begin.pClearValues = &clear;
        vkCmdBeginRenderPass(ctx.cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
        const VkViewport viewport{0.0f, 0.0f, float(mSize), float(mSize), 0.0f, 1.0f};
        const VkRect2D scissor{{0, 0}, {uint32_t(mSize), uint32_t(mSize)}};
        vkCmdSetViewport(ctx.cmd, 0, 1, &viewport);
        vkCmdSetScissor(ctx.cmd, 0, 1, &scissor);
        vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mDepthPipeline);
        ctx.frame.bind(ctx.cmd, mDepthLayout, ctx.frameOffset);
        const uint32_t offset = mLightStride * uint32_t(i);
        const VkDescriptorSet depthSet = mSets.set(kDepthSet);
        vkCmdBindDescriptorSets(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mDepthLayout, 1, 1, &depthSet, 1,
                                &offset);
        ctx.submitter.draw(ctx.cmd, mDepthLayout, DrawSet::Casters, mKeep);
        vkCmdEndRenderPass(ctx.cmd);
    }
}

void ShadowMapVulkan::execute(VulkanFrameContext& ctx) {
    const SubmitStats s = DepthLightingFrame::run(
        ctx, [&] { renderDepth(ctx); },
        [&] { drawLitScene(ctx, mLightingPipeline, mLightingLayout, mSets.set(kLightingSet)); });
    mCounters = ShadowMap::counters(s, mSize, mLights, mCulled);
}

} // namespace sb
