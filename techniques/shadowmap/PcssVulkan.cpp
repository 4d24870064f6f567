#include "techniques/shadowmap/PcssVulkan.h"

#include <algorithm>
#include <cstring>

#include "techniques/shadowmap/DepthLightingFrame.h"
#include "techniques/shadowmap/PoissonDisk.h"
#include "techniques/shadowmap/ShadowMapProperties.h"
#include "techniques/shadowmap/VulkanDepthMaps.h"
#include "techniques/vulkan/ScenePass.h"

namespace sb {

namespace {
using P = ShadowMapProperties;

/// std140 offsets of shadowmap/pcss.frag's ShadowMapBlock for `lights` lights.
struct BlockLayout {
    explicit BlockLayout(uint32_t lights)
        : light(64 * lights), search(80 * lights), blockerKernel(96 * lights),
          filterKernel(blockerKernel + 16 * Pcss::kMaxTaps), taps(filterKernel + 16 * Pcss::kMaxTaps),
          size(taps + 16) {}
    uint32_t light, search, blockerKernel, filterKernel, taps, size;
};

/// The search's and the filter's sampler: clamped to an opaque white border (depth 1, no caster outside
/// the map, as GL's border colour), nearest raw depths or a linear LEQUAL comparison.
VkSampler createSampler(VkDevice device, bool compare) {
    VkSamplerCreateInfo s{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    s.magFilter = s.minFilter = compare ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
    s.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    s.addressModeU = s.addressModeV = s.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
    s.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
    s.compareEnable = compare ? VK_TRUE : VK_FALSE;
    s.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    s.maxLod = 0.0f;
    VkSampler sampler = VK_NULL_HANDLE;
    VulkanContext::check(vkCreateSampler(device, &s, nullptr, &sampler), "vkCreateSampler (pcss)");
    return sampler;
}
} // namespace

PcssVulkan::PcssVulkan() : VulkanTechnique(Pcss::declaration()) {}

PcssVulkan::~PcssVulkan() {
    release();
}

void PcssVulkan::release() {
    if (!mDevice) return;
    for (VkFramebuffer f : mFramebuffers) vkDestroyFramebuffer(mDevice, f, nullptr);
    mFramebuffers.clear();
    vkDestroyRenderPass(mDevice, mDepthPass, nullptr);
    vkDestroySampler(mDevice, mSearchSampler, nullptr);
    vkDestroySampler(mDevice, mCompareSampler, nullptr);
    vkDestroyPipelineLayout(mDevice, mDepthLayout, nullptr);
    vkDestroyPipelineLayout(mDevice, mLightingLayout, nullptr);
    mDepthPass = VK_NULL_HANDLE;
    mSearchSampler = mCompareSampler = VK_NULL_HANDLE;
    mSets = DescriptorSets();
    mDepthLayout = mLightingLayout = VK_NULL_HANDLE;
    mMaps = VulkanImage();
}

void PcssVulkan::setScene(const Scene& scene) {
    mLights.setScene(scene, "pcss");
    mCulling.setScene(scene);
}

void PcssVulkan::sceneChanged(const Scene& scene, uint32_t) {
    setScene(scene);
    fitLightSizes(scene);
    writeBlocks();
}

void PcssVulkan::fitLightSizes(const Scene& scene) {
    mParams.clear();
    for (size_t i = 0; i < mLights.size(); ++i)
        mParams.push_back(Pcss::lightParams(scene, scene.lights[i], mLights.viewProj()[i],
                                            float(properties().getFloat(Pcss::kLightSize))));
}

void PcssVulkan::createMaps(VulkanContext& context) {
    const VkFormat format = VulkanDepthMaps::format(context.physicalDevice());
    mMaps = VulkanDepthMaps::image(context, format, uint32_t(mSize), uint32_t(mLayers), false);
    mDepthPass = VulkanDepthMaps::renderPass(mDevice, format);
    for (int i = 0; i < mLayers; ++i)
        mFramebuffers.push_back(
            VulkanDepthMaps::framebuffer(mDevice, mDepthPass, mMaps.layerView(uint32_t(i)), uint32_t(mSize)));
}

void PcssVulkan::createDescriptors(VulkanContext& context) {
    mSearchSampler = createSampler(mDevice, false);
    mCompareSampler = createSampler(mDevice, true);
    // Set 1 of the depth pass: the light's matrix, one dynamic slot per light (LightPass). Set 1 of the
    // lighting pass: the block and the map through each sampler.
    using D = DescriptorSets;
    mSets = DescriptorSets(
        mDevice,
        {{D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, VK_SHADER_STAGE_VERTEX_BIT)},
         {D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                     VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT),
          D::binding(1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT),
          D::binding(2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)}},
        "pcss");
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
    const VkImageLayout layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
    mSets.writeImage(kLightingSet, 1, mSearchSampler, mMaps.view(), layout);
    mSets.writeImage(kLightingSet, 2, mCompareSampler, mMaps.view(), layout);
}

void PcssVulkan::writeBlocks() {
    char* base = static_cast<char*>(mLightingBlock.map());
    if (!base) return;
    const BlockLayout block{uint32_t(mLayers)};
    const auto& shadow = mLights.shadowMatrices();
    for (size_t i = 0; i < shadow.size() && i < size_t(mLayers); ++i)
        std::memcpy(base + 64 * i, &shadow[i], sizeof(glm::mat4));
    for (size_t i = 0; i < mParams.size() && i < size_t(mLayers); ++i) {
        const glm::vec4 light = Pcss::lightVector(mParams[i]), search = Pcss::searchVector(mParams[i]);
        std::memcpy(base + block.light + 16 * i, &light, sizeof light);
        std::memcpy(base + block.search + 16 * i, &search, sizeof search);
    }
    for (size_t k = 0; k < mBlockerKernel.size() && k < size_t(Pcss::kMaxTaps); ++k)
        std::memcpy(base + block.blockerKernel + 16 * k, &mBlockerKernel[k], sizeof(glm::vec2));
    for (size_t k = 0; k < mFilterKernel.size() && k < size_t(Pcss::kMaxTaps); ++k)
        std::memcpy(base + block.filterKernel + 16 * k, &mFilterKernel[k], sizeof(glm::vec2));
    const glm::ivec2 taps(int(mBlockerKernel.size()), int(mFilterKernel.size()));
    std::memcpy(base + block.taps, &taps, sizeof taps);
    // The depth pass's light matrices: Vulkan's depth range, no flip (VulkanFrameBlock::depthFromGl).
    char* lights = static_cast<char*>(mLightPass.map());
    for (size_t i = 0; i < mLights.viewProj().size() && i < size_t(mLayers); ++i) {
        const glm::mat4 m = VulkanFrameBlock::depthFromGl() * mLights.viewProj()[i];
        std::memcpy(lights + mLightStride * i, &m, sizeof m);
    }
}

void PcssVulkan::compile(const VulkanCompileContext& ctx) {
    release();
    mDevice = ctx.context.device();
    const PropertySet& p = properties();
    mLayers = std::max<int>(1, int(mLights.size()));
    mSize = int(p.getInt(P::kResolution));
    createMaps(ctx.context);
    createDescriptors(ctx.context);
    mBlockerKernel = PoissonDisk::generate(int(p.getInt(Pcss::kBlockerTaps)));
    mFilterKernel = PoissonDisk::generate(int(p.getInt(Pcss::kFilterTaps)), Pcss::filterSeed());
    fitLightSizes(ctx.scene);
    writeBlocks();

    // Depth pass: casters only, depth with the bias of glPolygonOffset(slope, constant), no colour.
    mDepthLayout = createScenePipelineLayout(ctx, {mSets.layout(kDepthSet)});
    const Defines base = ctx.submitter.defines();
    std::string depthKey = "pcss-depth|bias=" + std::to_string(p.getFloat(P::kBiasSlope)) + "," +
                           std::to_string(p.getFloat(P::kBiasConstant)) + "|";
    GraphicsPipelineDesc depth =
        scenePipeline(ctx, "shadowmap/depth.vert", "shadowmap/depth.frag", base, mDepthLayout, depthKey);
    depth.depthBias = true;
    depth.depthBiasSlope = float(p.getFloat(P::kBiasSlope));
    depth.depthBiasConstant = float(p.getFloat(P::kBiasConstant));
    depth.colourAttachments = 0;
    depth.renderPass = mDepthPass;
    mDepthPipeline = ctx.pipelines.get(depthKey, depth);

    // Lighting pass: the GL form's defines.
    Defines lit = ctx.defines();
    lit["SHADOW_MAP"] = "";
    lit["LIGHT_COUNT"] = std::to_string(mLayers);
    mLightingLayout = createScenePipelineLayout(ctx, {mSets.layout(kLightingSet)});
    std::string litKey = "pcss-lighting|";
    GraphicsPipelineDesc lighting =
        scenePipeline(ctx, "common/scene.vert", "shadowmap/pcss.frag", lit, mLightingLayout, litKey);
    mLightingPipeline.build(ctx.pipelines, litKey, lighting, ctx.targets);
    setPermutationKey(definesKey(base) + "|" + definesKey(lit));
}

void PcssVulkan::renderDepth(VulkanFrameContext& ctx) {
    mCulled = 0;
    VkClearValue clear{};
    clear.depthStencil = {1.0f, 0};
    const VkViewport viewport{0.0f, 0.0f, float(mSize), float(mSize), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, {uint32_t(mSize), uint32_t(mSize)}};
    const VkDescriptorSet depthSet = mSets.set(kDepthSet);
    for (size_t i = 0; i < mLights.viewProj().size(); ++i) {
        if (!mLights.castsShadow(i)) continue;
        mCulled += mLights.cullCasters(i, mCulling, mKeep, nullptr);
        VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        begin.renderPass = mDepthPass;
        begin.framebuffer = mFramebuffers[i];
        begin.renderArea.extent = {uint32_t(mSize), uint32_t(mSize)};
        begin.clearValueCount = 1;
        begin.pClearValues = &clear;
        vkCmdBeginRenderPass(ctx.cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
        vkCmdSetViewport(ctx.cmd, 0, 1, &viewport);
        vkCmdSetScissor(ctx.cmd, 0, 1, &scissor);
        vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mDepthPipeline);
        ctx.frame.bind(ctx.cmd, mDepthLayout, ctx.frameOffset);
        const uint32_t offset = mLightStride * uint32_t(i);
        vkCmdBindDescriptorSets(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mDepthLayout, 1, 1, &depthSet, 1,
                                &offset);
        ctx.submitter.draw(ctx.cmd, mDepthLayout, DrawSet::Casters, mKeep);
        vkCmdEndRenderPass(ctx.cmd);
    }
}

void PcssVulkan::execute(VulkanFrameContext& ctx) {
    const SubmitStats s = DepthLightingFrame::run(
        ctx, [&] { renderDepth(ctx); },
        [&] { drawLitScene(ctx, mLightingPipeline, mLightingLayout, mSets.set(kLightingSet)); });
    mCounters = Pcss::counters(s, mSize, mLights.size(), mLights.shadowed(), mCulled, mBlockerKernel.size(),
                               mFilterKernel.size(), mParams);
}

} // namespace sb
