#include "techniques/shadowmap/ShadowMapVulkan.h"

#include <algorithm>
#include <cstring>

#include "core/Error.h"
#include "scenes/ShadowWork.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/shadowmap/DepthLightingFrame.h"
#include "techniques/shadowmap/ShadowMap.h"
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
    vkDestroyPipelineLayout(mDevice, mDepthLayout, nullptr);
    vkDestroyPipelineLayout(mDevice, mLightingLayout, nullptr);
    mSets = DescriptorSets();
    mDepthLayout = mLightingLayout = VK_NULL_HANDLE;
    mMaps = VulkanDepthMapSet();
}

void ShadowMapVulkan::setScene(const Scene& scene) {
    mLights.setScene(scene, "shadowmap", properties());
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

void ShadowMapVulkan::createDescriptors(VulkanContext& context) {
    const VkSampler sampler = mMaps.addSampler(properties().getBool("hardware_compare"));
    mMaps.createSlots(context, sizeof(glm::mat4), uint32_t(mLayers));
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
    const BlockLayout block{uint32_t(mLayers)};
    mLightingBlock = VulkanBuffer(context, block.size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memset(mLightingBlock.map(), 0, block.size);
    mSets.writeBuffer(kDepthSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, mMaps.slots().buffer(),
                      mMaps.slots().bytes());
    mSets.writeBuffer(kLightingSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, mLightingBlock.buffer(),
                      block.size);
    mSets.writeImage(kLightingSet, 1, sampler, mMaps.view(), VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
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
    for (size_t i = 0; i < mLights.viewProj().size() && i < size_t(mLayers); ++i) {
        const glm::mat4 m = VulkanFrameBlock::depthFromGl() * mLights.viewProj()[i];
        mMaps.slots().write(i, &m, sizeof m);
    }
}

void ShadowMapVulkan::compile(const VulkanCompileContext& ctx) {
    release();
    mDevice = ctx.context.device();
    const PropertySet& p = properties();
    mLayers = std::max<int>(1, int(mLights.size()));
    mSize = int(p.getInt(P::kResolution));
    mMaps = VulkanDepthMapSet(ctx.context, uint32_t(mSize), uint32_t(mLayers), uint32_t(mLayers));
    createDescriptors(ctx.context);

    // Depth pass: casters only, depth with the bias of glPolygonOffset(slope, constant), no colour, no
    // fragment stage.
    mDepthLayout = createScenePipelineLayout(ctx, {mSets.layout(kDepthSet)});
    const Defines base = ctx.submitter.defines();
    std::string depthKey = "shadowmap-depth" + VulkanDepthMapSet::biasKey(p);
    GraphicsPipelineDesc depth = scenePipeline(ctx, "common/depth.vert", VulkanDepthMapSet::kDepthFragment,
                                               base, mDepthLayout, depthKey);
    mMaps.depthPipeline(depth, p);
    mDepthPipeline = ctx.pipelines.get(depthKey, depth);

    // Lighting pass: the declaration's defines, the GL form's permutation for permutation.
    const Defines lit = ShadowMap::lightingDefines(ctx.defines(), p, mLayers);
    mKernel = ShadowMap::kernelOffsets(p);
    mNormalOffset = float(p.getFloat(ShadowMap::kNormalOffset));
    mCull = p.getBool(ShadowMap::kCull);
    fitTexels(ctx.scene);
    writeLightingBlock(float(ctx.targets.height()));
    mLightingLayout = createScenePipelineLayout(ctx, {mSets.layout(kLightingSet)});
    setPermutationKey(definesKey(base) + "|" +
                      mLighting.build(ctx, "common/scene.vert", "shadowmap/lighting.frag", lit,
                                      mLightingLayout, "shadowmap-lighting|"));
}

void ShadowMapVulkan::renderDepth(VulkanFrameContext& ctx) {
    mCulled = 0;
    mView.reach.camera = ctx.proj * ctx.view;
    for (size_t i = 0; i < mLights.viewProj().size(); ++i) {
        if (!mLights.castsShadow(i)) continue;
        mCulled += mLights.cullCasters(i, mCulling, mKeep, mCull ? &mView : nullptr);
        mMaps.begin(ctx.cmd, i);
        vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mDepthPipeline);
        ctx.frame.bind(ctx.cmd, mDepthLayout, ctx.frameOffset);
        mMaps.slots().bind(ctx.cmd, mDepthLayout, mSets.set(kDepthSet), i);
        // The nearest caster per texel: closed casters' back faces can go (scenes/BackFaceCulling.h).
        ctx.submitter.drawCulled(ctx.cmd, mDepthLayout, DrawSet::Casters, {mLights.viewProj()[i], false},
                                 false, mKeep);
        vkCmdEndRenderPass(ctx.cmd);
    }
}

void ShadowMapVulkan::renderLighting(VulkanFrameContext& ctx) {
    mLighting.draw(ctx, mLightingLayout, mSets.set(kLightingSet));
}

void ShadowMapVulkan::execute(VulkanFrameContext& ctx) {
    const SubmitStats s = DepthLightingFrame::run(
        ctx, [&] { renderDepth(ctx); }, [&] { renderLighting(ctx); });
    mCounters = ShadowMap::counters(s, mSize, mLights, mCulled);
}

} // namespace sb
