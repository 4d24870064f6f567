#include "techniques/shadowmap/VulkanMomentMaps.h"

#include <algorithm>
#include <cstring>

#include "scenes/ShadowWork.h"
#include "techniques/ContactShadows.h"
#include "techniques/vulkan/ScenePass.h"
#include "techniques/vulkan/VulkanDepthMaps.h"
#include "vk/LayerPasses.h"

namespace sb {

namespace {
/// std140 offsets of vsm.frag's and esm.frag's ShadowMapBlock for `lights` lights.
struct BlockLayout {
    explicit BlockLayout(uint32_t lights)
        : plane(64 * lights), point(80 * lights), margin(96 * lights), params(margin + 4), size(margin + 16) {
    }
    uint32_t plane, point, margin, params, size;
};

/// moments.vert's LightPass: the light's matrix and depth parameters.
constexpr VkDeviceSize kLightPassBytes = sizeof(glm::mat4) + 2 * sizeof(glm::vec4);

/// The colour layer cleared and left SHADER_READ_ONLY for the lighting pass; the depth cleared and
/// dropped. Before: the previous frame's reads and blur writes of the layer and the previous layer's
/// depth writes. After: the blur's and the lighting pass's reads.
VkRenderPass createPass(VkDevice device, VkFormat colour, VkFormat depth) {
    LayerPasses::PassDesc desc;
    desc.colour = LayerPasses::Attachment{colour, VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_STORE,
                                          VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    desc.depth = LayerPasses::Attachment{depth, VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_DONT_CARE,
                                         VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    const VkPipelineStageFlags tests =
        VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    desc.before = {VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                       tests,
                   VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | tests,
                   VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                   VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                       VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT};
    desc.after = {VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                  VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT};
    return LayerPasses::renderPass(device, desc, "moments");
}
} // namespace

VulkanMomentMaps::~VulkanMomentMaps() {
    release();
}

void VulkanMomentMaps::release() {
    if (!mDevice) return;
    for (VkFramebuffer f : mFramebuffers) vkDestroyFramebuffer(mDevice, f, nullptr);
    mFramebuffers.clear();
    vkDestroyRenderPass(mDevice, mPass, nullptr);
    vkDestroySampler(mDevice, mSampler, nullptr);
    vkDestroyPipelineLayout(mDevice, mDepthLayout, nullptr);
    vkDestroyPipelineLayout(mDevice, mLightingLayout, nullptr);
    mPass = VK_NULL_HANDLE;
    mSampler = VK_NULL_HANDLE;
    mDepthLayout = mLightingLayout = VK_NULL_HANDLE;
    mSets = DescriptorSets();
    mMaps = VulkanImage();
    mDepth = VulkanImage();
}

void VulkanMomentMaps::sceneChanged(const Scene& scene) {
    mFits.sceneChanged(scene);
    writeBlocks();
}

void VulkanMomentMaps::createImages(VulkanContext& context) {
    const uint32_t size = uint32_t(mSettings.resolution), layers = uint32_t(mLayers);
    VulkanImageDesc d;
    d.width = d.height = size;
    d.layers = layers;
    d.format = mSettings.format;
    d.usage =
        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    d.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    mMaps = VulkanImage(context, d);
    // Every layer "no occluder" and sampleable: a light that casts no shadow is never rendered.
    context.submitNow([&](VkCommandBuffer cmd) {
        transitionImage(cmd, mMaps.image(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, layers);
        VkClearColorValue clear{};
        std::memcpy(clear.float32, &mSettings.clear, sizeof clear.float32);
        const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, layers};
        vkCmdClearColorImage(cmd, mMaps.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &clear, 1, &range);
        transitionImage(cmd, mMaps.image(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, layers);
    });
    mDepthFormat = VulkanDepthMaps::format(context.physicalDevice());
    VulkanImageDesc depth;
    depth.width = depth.height = size;
    depth.format = mDepthFormat;
    depth.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    depth.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    mDepth = VulkanImage(context, depth);
    mPass = createPass(mDevice, mSettings.format, mDepthFormat);
    // Every layer's pass reuses the one depth attachment: the passes run one after another.
    mFramebuffers = LayerPasses::layerFramebuffers(mDevice, mPass, mMaps, layers, "moments", mDepth.view());
}

void VulkanMomentMaps::createDescriptors(VulkanContext& context) {
    // Bilinear, clamp to edge, as GL's texture parameters.
    mSampler = LayerPasses::sampler(mDevice, LayerPasses::Sampling{}, "moments");
    using D = DescriptorSets;
    const VkShaderStageFlags both = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    mSets = DescriptorSets(
        mDevice,
        {{D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, both)},
         {D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, both),
          D::binding(1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)}},
        mOwner.c_str());
    mLightStride = context.uniformStride(kLightPassBytes);
    mLightPass = VulkanBuffer(context, VkDeviceSize(mLightStride) * uint32_t(mLayers),
                              VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memset(mLightPass.map(), 0, size_t(mLightStride) * uint32_t(mLayers));
    const BlockLayout block{uint32_t(mLayers)};
    mLightingBlock = VulkanBuffer(context, block.size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memset(mLightingBlock.map(), 0, block.size);
    mSets.writeBuffer(kDepthSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, mLightPass.buffer(),
                      kLightPassBytes);
    mSets.writeBuffer(kLightingSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, mLightingBlock.buffer(),
                      block.size);
    mSets.writeImage(kLightingSet, 1, mSampler, mMaps.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

void VulkanMomentMaps::writeBlocks() {
    char* base = static_cast<char*>(mLightingBlock.map());
    char* lights = static_cast<char*>(mLightPass.map());
    if (!base || !lights) return;
    const BlockLayout block{uint32_t(mLayers)};
    const size_t n = std::min(mFits.lights(), size_t(mLayers));
    for (size_t i = 0; i < n && i < mFits.viewProjections().size(); ++i) {
        std::memcpy(base + 64 * i, &mFits.shadowMatrices()[i], sizeof(glm::mat4));
        std::memcpy(base + block.plane + 16 * i, &mFits.depthPlanes()[i], sizeof(glm::vec4));
        std::memcpy(base + block.point + 16 * i, &mFits.depthPoints()[i], sizeof(glm::vec4));
        // The depth pass: Vulkan's depth range, no flip (VulkanFrameBlock::depthFromGl).
        const glm::mat4 m = VulkanFrameBlock::depthFromGl() * mFits.viewProjections()[i];
        char* slot = lights + size_t(mLightStride) * i;
        std::memcpy(slot, &m, sizeof m);
        std::memcpy(slot + 64, &mFits.depthPlanes()[i], sizeof(glm::vec4));
        std::memcpy(slot + 80, &mFits.depthPoints()[i], sizeof(glm::vec4));
    }
    const float margin = mFits.marginUv(mSettings.resolution);
    std::memcpy(base + block.margin, &margin, sizeof margin);
    std::memcpy(base + block.params, &mSettings.params, sizeof(glm::vec2));
}

void VulkanMomentMaps::createPipelines(const VulkanCompileContext& ctx) {
    // The depth pass: moments into colour 0; casters LESS, the background non-casters GREATER.
    mDepthLayout = createScenePipelineLayout(ctx, {mSets.layout(kDepthSet)});
    std::string depthKey = mOwner + "-moments|format=" + std::to_string(int(mSettings.format)) + "|";
    GraphicsPipelineDesc depth = scenePipeline(ctx, "shadowmap/moments.vert", "shadowmap/moments.frag",
                                               mSettings.depthDefines, mDepthLayout, depthKey);
    depth.renderPass = mPass;
    mCasterPipeline = ctx.pipelines.get(depthKey + "|less", depth);
    depth.depthCompare = VK_COMPARE_OP_GREATER;
    // The farthest surface: both faces, fixed (a closed mesh's farthest surface is a back face).
    depth.dynamicCull = false;
    mBackgroundPipeline = ctx.pipelines.get(depthKey + "|greater|both-faces", depth);

    Defines lit = mSettings.lightingDefines;
    lit["SHADOW_MAP"] = ""; // common/scene.vert: vShadowCoord[i] = uShadowMatrix[i] * world
    lit["LIGHT_COUNT"] = std::to_string(mLayers);
    mLightingLayout = createScenePipelineLayout(ctx, mContact.lightingSets({mSets.layout(kLightingSet)}));
    const std::string litPermutation = mLighting.build(ctx, "common/scene.vert", mSettings.lightingFragment,
                                                       lit, mLightingLayout, mOwner + "-lighting|");
    mKey = definesKey(mSettings.depthDefines) + "|" + litPermutation;
}

std::string VulkanMomentMaps::compile(const VulkanCompileContext& ctx, const Settings& settings) {
    release();
    mDevice = ctx.context.device();
    mSettings = settings;
    mLayers = std::max<int>(1, int(mFits.lights()));
    createImages(ctx.context);
    createDescriptors(ctx.context);
    writeBlocks();
    createPipelines(ctx);
    mHasCasters.assign(size_t(mLayers), 0);
    VulkanSeparableBlur::Settings blur = settings.blur;
    blur.resolution = settings.resolution;
    blur.format = settings.format;
    const std::string blurKey = mBlur.compile(ctx.context, ctx.shaders, ctx.pipelines, blur, mMaps);
    return blurKey.empty() ? mKey : mKey + "|" + blurKey;
}

void VulkanMomentMaps::renderLayer(VulkanFrameContext& ctx, size_t light,
                                   const MomentMapFits::LightDraws& draws) {
    const uint32_t size = uint32_t(mSettings.resolution);
    VkClearValue clear[2]{};
    std::memcpy(clear[0].color.float32, &mSettings.clear, sizeof clear[0].color.float32);
    clear[1].depthStencil = {draws.background ? 0.0f : 1.0f, 0};
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = mPass;
    begin.framebuffer = mFramebuffers[light];
    begin.renderArea.extent = {size, size};
    begin.clearValueCount = 2;
    begin.pClearValues = clear;
    vkCmdBeginRenderPass(ctx.cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    if (draws.casters > 0) { // else the layer stays "no occluder"
        const VkViewport viewport{0.0f, 0.0f, float(size), float(size), 0.0f, 1.0f};
        const VkRect2D scissor{{0, 0}, {size, size}};
        vkCmdSetViewport(ctx.cmd, 0, 1, &viewport);
        vkCmdSetScissor(ctx.cmd, 0, 1, &scissor);
        ctx.frame.bind(ctx.cmd, mDepthLayout, ctx.frameOffset);
        const uint32_t offset = mLightStride * uint32_t(light);
        const VkDescriptorSet set = mSets.set(kDepthSet);
        vkCmdBindDescriptorSets(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mDepthLayout, 1, 1, &set, 1,
                                &offset);
        if (draws.background) {
            // The farthest non-caster per texel: every non-caster there lies at or in front of it.
            vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mBackgroundPipeline);
            ctx.submitter.draw(ctx.cmd, mDepthLayout, DrawSet::NonCasters, mKeepBackground);
            VkClearAttachment far{VK_IMAGE_ASPECT_DEPTH_BIT, 0, {}};
            far.clearValue.depthStencil = {1.0f, 0};
            const VkClearRect rect{scissor, 0, 1};
            vkCmdClearAttachments(ctx.cmd, 1, &far, 1, &rect);
        }
        // The nearest caster per texel, over whatever the background left.
        vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mCasterPipeline);
        // The nearest caster may lose closed casters' back faces; the background above keeps both.
        ctx.submitter.drawCulled(ctx.cmd, mDepthLayout, DrawSet::Casters,
                                 {mFits.viewProjections()[light], false}, false, mKeep);
    }
    vkCmdEndRenderPass(ctx.cmd);
}

void VulkanMomentMaps::render(VulkanFrameContext& ctx) {
    mCulled = 0;
    const glm::mat4 camera = ctx.proj * ctx.view;
    for (size_t i = 0; i < mFits.lights() && i < mFramebuffers.size(); ++i) {
        if (!mFits.castsShadow(i)) { // never looked up (common/lighting.glsl): neither cleared nor blurred
            mHasCasters[i] = 0;
            continue;
        }
        const MomentMapFits::LightDraws draws =
            mFits.cull(i, ctx.scene, camera, mKeep, mKeepBackground, mCulled);
        mHasCasters[i] = draws.casters > 0;
        renderLayer(ctx, i, draws);
    }
}

Counters VulkanMomentMaps::renderFrame(VulkanFrameContext& ctx) {
    ctx.submitter.resetStats();
    double blurTexels = 0.0;
    const std::function<void()> viewDepth = mContact.prePass(ctx);
    if (const char* reason = ShadowWork::noneNeeded(ctx.scene)) {
        if (viewDepth) ctx.passes.skip(ContactShadows::kPass, reason);
        ctx.passes.skip("depth", reason);
        ctx.passes.skip("blur", reason);
    } else {
        if (viewDepth) {
            ctx.passes.begin(ContactShadows::kPass);
            viewDepth();
        }
        ctx.passes.begin("depth");
        render(ctx);
        if (mBlur.radius() > 0) {
            ctx.passes.begin("blur");
            blurTexels = mBlur.apply(ctx.cmd, mHasCasters);
        } else {
            ctx.passes.skip("blur", "blur below 2 texels: a one-tap kernel");
        }
    }
    ctx.passes.begin("lighting");
    mContact.bind(ctx.cmd, mLightingLayout);
    mLighting.draw(ctx, mLightingLayout, mSets.set(kLightingSet));
    return mFits.counters(ctx.submitter.stats(), mSettings.resolution, blurTexels, mCulled);
}

} // namespace sb
