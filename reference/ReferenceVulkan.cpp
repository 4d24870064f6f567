#include "reference/ReferenceVulkan.h"

#include <algorithm>

#include "reference/Reference.h"
#include "scenes/Motion.h"
#include "shading/ShaderLimits.h"
#include "techniques/vulkan/ScenePass.h"

namespace sb {

namespace {
constexpr VkFormat kVisibilityFormat = VK_FORMAT_R32G32B32A32_SFLOAT; // GL's RGBA32F texture
} // namespace

ReferenceVulkan::ReferenceVulkan() : VulkanTechnique(Reference::declaration()) {}

ReferenceVulkan::~ReferenceVulkan() {
    release();
}

void ReferenceVulkan::release() {
    mGBufferRenderer.reset();
    if (mLayout) vkDestroyPipelineLayout(mDevice, mLayout, nullptr);
    if (mSampler) vkDestroySampler(mDevice, mSampler, nullptr);
    mLayout = VK_NULL_HANDLE;
    mSampler = VK_NULL_HANDLE;
    mSets = DescriptorSets();
    mStaging = VulkanBuffer();
    mVisibilityImage = VulkanImage();
    mWidth = mHeight = 0;
}

void ReferenceVulkan::sceneChanged(const Scene& scene, uint32_t changes) {
    if (changes & kCastersMoved) setScene(scene);
}

void ReferenceVulkan::setScene(const Scene& scene) {
    // Tracer first: it holds a reference to the Embree scene it replaces.
    mTracer.reset();
    mEmbree = std::make_unique<EmbreeScene>(scene);
    mTracer = std::make_unique<ReferenceTracer>(scene, *mEmbree);
    mScene = &scene;
}

void ReferenceVulkan::ensureTargets(const VulkanCompileContext& ctx) {
    const int w = ctx.targets.width(), h = ctx.targets.height();
    if (w == mWidth && h == mHeight && mGBufferRenderer) return;
    release();
    mDevice = ctx.context.device();
    mGBufferRenderer =
        std::make_unique<VulkanGBufferRenderer>(ctx.context, ctx.shaders, ctx.submitter, ctx.frame, w, h);
    VulkanImageDesc d;
    d.width = uint32_t(w);
    d.height = uint32_t(h);
    d.format = kVisibilityFormat;
    d.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    mVisibilityImage = VulkanImage(ctx.context, d);
    mStaging =
        VulkanBuffer(ctx.context, VkDeviceSize(w) * VkDeviceSize(h) * 16, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    ctx.context.submitNow([&](VkCommandBuffer cmd) {
        transitionImage(cmd, mVisibilityImage.image(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    });
    // texelFetch reads no filter, but a combined image sampler needs one: nearest, as GL's texture.
    VkSamplerCreateInfo s{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    s.magFilter = s.minFilter = VK_FILTER_NEAREST;
    s.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    s.addressModeU = s.addressModeV = s.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    VulkanContext::check(vkCreateSampler(mDevice, &s, nullptr, &mSampler), "vkCreateSampler (reference)");
    mSets = DescriptorSets(mDevice,
                           {{DescriptorSets::binding(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                                                     VK_SHADER_STAGE_FRAGMENT_BIT)}},
                           "reference");
    mSets.writeImage(0, 0, mSampler, mVisibilityImage.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    mLayout = createScenePipelineLayout(ctx, {mSets.layout(0)});
    mWidth = w;
    mHeight = h;
}

void ReferenceVulkan::compile(const VulkanCompileContext& ctx) {
    ensureTargets(ctx);
    Defines shade = ctx.submitter.defines();
    shade["LIGHT_COUNT"] = std::to_string(std::clamp<int>(int(ctx.scene.lights.size()), 1, kMaxLights));
    addLightingRateDefines(ctx.scene, shade); // shaded as the techniques it is compared with
    std::string key;
    GraphicsPipelineDesc desc =
        scenePipeline(ctx, "common/scene.vert", "reference/shade.frag", shade, mLayout, key);
    mShadePipeline.build(ctx.pipelines, key, desc, ctx.targets);
    setPermutationKey(definesKey(ctx.submitter.defines()) + "|" + definesKey(shade));
}

void ReferenceVulkan::trace() {
    const ReferenceTracer::Options options = Reference::tracerOptions(properties());
    const size_t lights = std::min<size_t>(mScene->lights.size(), kMaxLights);
    mVisibility.assign(lights, {});
    mTraceStats.assign(lights, {});
    for (size_t i = 0; i < lights; ++i)
        mVisibility[i] = mTracer->trace(mGBuffer, int(i), options, &mTraceStats[i]);
}

void ReferenceVulkan::writeVisibility() {
    // The previous frame's copy has finished (the harness waited for its fence): the buffer is free.
    Reference::packVisibility(mVisibility, mWidth, mHeight, true, static_cast<float*>(mStaging.map()));
}

void ReferenceVulkan::recordUpload(VkCommandBuffer cmd) {
    transitionImage(cmd, mVisibilityImage.image(), VK_IMAGE_ASPECT_COLOR_BIT,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {uint32_t(mWidth), uint32_t(mHeight), 1};
    vkCmdCopyBufferToImage(cmd, mStaging.buffer(), mVisibilityImage.image(),
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    transitionImage(cmd, mVisibilityImage.image(), VK_IMAGE_ASPECT_COLOR_BIT,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

void ReferenceVulkan::execute(VulkanFrameContext& ctx) {
    ctx.passes.begin("gbuffer");
    mGBuffer = mGBufferRenderer->render(ctx.submitter, ctx.frameOffset);
    ctx.passes.begin("trace");
    trace();
    writeVisibility();
    ctx.passes.begin("shade");
    recordUpload(ctx.cmd);
    ctx.submitter.resetStats();
    // The harness cleared depth before execute() and the G-buffer drew into its own images, so the
    // depth test (LESS) resolves the same visible surface per pixel as the G-buffer did.
    drawLitScene(ctx, mShadePipeline, mLayout, mSets.set(0));
    mCounters = Reference::counters(mGBufferRenderer->lastStats() + ctx.submitter.stats(), mTraceStats);
}

} // namespace sb
