#include "techniques/shadowmap/ShadowMapVulkan.h"

#include <algorithm>
#include <cstring>

#include "core/Error.h"
#include "scenes/ShadowWork.h"
#include "techniques/ContactShadows.h"
#include "techniques/DepthLightingFrame.h"
#include "techniques/ShadowMapProperties.h"
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
    vkDestroyPipelineLayout(mDevice, mLightingLayout, nullptr);
    mSets = DescriptorSets();
    mLightingLayout = VK_NULL_HANDLE;
    mDepth = VulkanFlatDepthPass();
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
    const VkSampler sampler = mDepth.maps().addSampler(properties().getBool("hardware_compare"));
    // Set 1 of the lighting pass: ShadowMapBlock and the map.
    using D = DescriptorSets;
    mSets = DescriptorSets(
        mDevice,
        {{D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                     VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT),
          D::binding(1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)}},
        "shadowmap");
    const BlockLayout block{uint32_t(mLayers)};
    mLightingBlock = VulkanBuffer(context, block.size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memset(mLightingBlock.map(), 0, block.size);
    mSets.writeBuffer(0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, mLightingBlock.buffer(), block.size);
    mSets.writeImage(0, 1, sampler, mDepth.maps().view(), VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
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
    mDepth.writeLights(mLights);
}

void ShadowMapVulkan::propertiesApplied() {
    mutableInfo().passes = ContactShadows::passes(properties(), ShadowMap::declaration().passes);
}

void ShadowMapVulkan::compile(const VulkanCompileContext& ctx) {
    release();
    mDevice = ctx.context.device();
    const PropertySet& p = properties();
    mLayers = std::max<int>(1, int(mLights.size()));
    mSize = int(p.getInt(P::kResolution));
    // Depth pass: casters only, depth with the bias of glPolygonOffset(slope, constant).
    mDepth = VulkanFlatDepthPass(ctx, "shadowmap", uint32_t(mSize), uint32_t(mLayers),
                                 p.getFloat(P::kBiasSlope), p.getFloat(P::kBiasConstant));
    createDescriptors(ctx.context);
    const Defines base = ctx.submitter.defines();

    // Lighting pass: the declaration's defines, the GL form's permutation for permutation.
    const Defines lit = ShadowMap::lightingDefines(ctx.defines(), p, mLayers);
    mKernel = ShadowMap::kernelOffsets(p);
    mNormalOffset = float(p.getFloat(ShadowMap::kNormalOffset));
    mCull = p.getBool(ShadowMap::kCull);
    fitTexels(ctx.scene);
    writeLightingBlock(float(ctx.targets.height()));
    mContact.compile(p, ctx);
    mLightingLayout = createScenePipelineLayout(ctx, mContact.lightingSets({mSets.layout(0)}));
    setPermutationKey(definesKey(base) + "|" +
                      mLighting.build(ctx, "common/scene.vert", "shadowmap/lighting.frag", lit,
                                      mLightingLayout, "shadowmap-lighting|"));
}

void ShadowMapVulkan::renderDepth(VulkanFrameContext& ctx) {
    mView.reach.camera = ctx.proj * ctx.view;
    mCulled = mDepth.record(ctx, mLights, mCulling, mCull ? &mView : nullptr);
}

void ShadowMapVulkan::renderLighting(VulkanFrameContext& ctx) {
    mContact.bind(ctx.cmd, mLightingLayout);
    mLighting.draw(ctx, mLightingLayout, mSets.set(0));
}

void ShadowMapVulkan::execute(VulkanFrameContext& ctx) {
    const SubmitStats s = DepthLightingFrame::run(
        ctx, [&] { renderDepth(ctx); }, [&] { renderLighting(ctx); }, mContact.prePass(ctx),
        ContactShadows::kPass);
    mCounters = ShadowMap::counters(s, mSize, mLights, mCulled);
}

} // namespace sb
