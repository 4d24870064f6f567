#include "techniques/projective/ProjectiveVulkan.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/Error.h"
#include "shading/ShaderLimits.h"
#include "techniques/vulkan/ScenePass.h"
#include "vk/LayerPasses.h"

namespace sb {

namespace {
constexpr size_t kTextureSet = 0, kLightingSet = 1; // in mSets
} // namespace

ProjectiveVulkan::ProjectiveVulkan() : VulkanTechnique(Projective::declaration()) {}

ProjectiveVulkan::~ProjectiveVulkan() {
    release();
}

void ProjectiveVulkan::release() {
    if (!mDevice) return;
    for (VkFramebuffer fb : mFramebuffers) vkDestroyFramebuffer(mDevice, fb, nullptr);
    mFramebuffers.clear();
    vkDestroyRenderPass(mDevice, mTexturePass, nullptr);
    vkDestroySampler(mDevice, mSampler, nullptr);
    vkDestroyPipelineLayout(mDevice, mTextureLayout, nullptr);
    vkDestroyPipelineLayout(mDevice, mLightingLayout, nullptr);
    mTexturePass = VK_NULL_HANDLE;
    mSampler = VK_NULL_HANDLE;
    mTextureLayout = mLightingLayout = VK_NULL_HANDLE;
    mSets = DescriptorSets();
    mProjectors = VulkanBuffer();
    mMatrices = VulkanBuffer();
    mArray = VulkanImage();
}

void ProjectiveVulkan::setScene(const Scene& scene) {
    mCulling.setScene(scene);
    mPlan = Projective::plan(scene, properties());
}

void ProjectiveVulkan::sceneChanged(const Scene& scene, uint32_t) {
    // The sun of a scene in motion turns: GL reads the refitted matrices as uniforms every frame, here
    // the buffers the frames read are rewritten (the frame before has been waited for).
    setScene(scene);
    writeMatrices();
}

void ProjectiveVulkan::writeMatrices() {
    char* projectors = static_cast<char*>(mProjectors.map());
    char* matrices = static_cast<char*>(mMatrices.map());
    if (!projectors || !matrices) return; // before compile
    for (size_t i = 0; i < mPlan.viewProj.size(); ++i) {
        // The silhouette is sampled, not shown: Vulkan's depth range, no flip (depthFromGl).
        const glm::mat4 m = VulkanFrameBlock::depthFromGl() * mPlan.viewProj[i];
        std::memcpy(projectors + size_t(mStride) * i, &m, sizeof m);
        std::memcpy(matrices + sizeof(glm::mat4) * i, &mPlan.textureMatrix[i], sizeof(glm::mat4));
    }
}

void ProjectiveVulkan::createTextures(VulkanContext& context, uint32_t layers) {
    VulkanImageDesc d;
    d.width = d.height = uint32_t(mResolution);
    d.layers = layers;
    d.format = VK_FORMAT_R8_UNORM;
    d.usage =
        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    d.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    mArray = VulkanImage(context, d);
    // Layers no frame draws (a light that casts no shadow) are never looked up; white (lit) anyway.
    context.submitNow([&](VkCommandBuffer cmd) {
        transitionImage(cmd, mArray.image(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, layers);
        const VkClearColorValue white{{1.0f, 1.0f, 1.0f, 1.0f}};
        const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, layers};
        vkCmdClearColorImage(cmd, mArray.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &white, 1, &range);
        transitionImage(cmd, mArray.image(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, layers);
    });
    // One colour attachment cleared to white (lit) and left for the lighting pass to sample.
    mTexturePass =
        LayerPasses::colourPass(mDevice, VK_FORMAT_R8_UNORM, VK_ATTACHMENT_LOAD_OP_CLEAR, "projective");
    mFramebuffers = LayerPasses::layerFramebuffers(mDevice, mTexturePass, mArray, layers, "projective");
}

void ProjectiveVulkan::createDescriptors(VulkanContext& context, uint32_t layers) {
    // Bilinear lookups; outside the projector's frustum no caster was drawn: a white (lit) border.
    LayerPasses::Sampling border;
    border.whiteBorder = true;
    mSampler = LayerPasses::sampler(mDevice, border, "projective");

    using D = DescriptorSets;
    mSets = DescriptorSets(
        mDevice,
        {{D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, VK_SHADER_STAGE_VERTEX_BIT)},
         {D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT),
          D::binding(1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)}},
        "projective");
    mStride = context.uniformStride(sizeof(glm::mat4));
    mProjectors = VulkanBuffer(context, VkDeviceSize(mStride) * layers, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    mMatrices = VulkanBuffer(context, sizeof(glm::mat4) * layers, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memset(mProjectors.map(), 0, size_t(mStride) * layers);
    std::memset(mMatrices.map(), 0, sizeof(glm::mat4) * layers);
    writeMatrices();
    mSets.writeBuffer(kTextureSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, mProjectors.buffer(),
                      sizeof(glm::mat4));
    mSets.writeBuffer(kLightingSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, mMatrices.buffer(),
                      sizeof(glm::mat4) * layers);
    mSets.writeImage(kLightingSet, 1, mSampler, mArray.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

void ProjectiveVulkan::buildPipelines(const VulkanCompileContext& ctx) {
    const Defines base = withLightKinds(ctx.submitter.defines(), ctx.scene);
    // Casters (and, without projectors, everything): lit and unshadowed, as `none` draws them.
    Defines lit = base;
    lit["LIGHT_COUNT"] = std::to_string(std::clamp<int>(int(ctx.scene.lights.size()), 1, kMaxLights));
    std::string litKey = "projective-lit|";
    mLit.build(ctx.pipelines, litKey,
               scenePipeline(ctx, "common/scene.vert", "common/lit.frag", lit, mLightingLayout, litKey),
               ctx.targets);
    std::string key = definesKey(lit);
    mTexturePipeline = VK_NULL_HANDLE;
    if (mPlan.viewProj.empty()) {
        setPermutationKey(key);
        return;
    }
    // A silhouette: every caster fragment is black, whatever its depth (no depth attachment at all).
    std::string textureKey = "projective-texture|";
    GraphicsPipelineDesc texture = scenePipeline(ctx, "projective/texture.vert", "projective/texture.frag",
                                                 base, mTextureLayout, textureKey);
    texture.depthTest = false;
    texture.depthWrite = false;
    texture.renderPass = mTexturePass;
    mTexturePipeline = ctx.pipelines.get(textureKey, texture);

    Defines projective = ctx.defines(); // its lookups follow the scene's exceptions
    projective["SHADOW_MAP"] = "";      // common/scene.vert: vShadowCoord[i] = uShadowMatrix[i] * world
    projective["LIGHT_COUNT"] = std::to_string(mPlan.viewProj.size());
    std::string projectiveKey = "projective-lighting|";
    mProjective.build(ctx.pipelines, projectiveKey,
                      scenePipeline(ctx, "common/scene.vert", "projective/lighting.frag", projective,
                                    mLightingLayout, projectiveKey),
                      ctx.targets);
    setPermutationKey(key + "|" + definesKey(base) + "|" + definesKey(projective));
}

void ProjectiveVulkan::compile(const VulkanCompileContext& ctx) {
    release();
    mDevice = ctx.context.device();
    const PropertySet& p = properties();
    mResolution = int(p.getInt(Projective::kResolution));
    mBlurRadius = int(p.getInt(Projective::kBlur));
    mCull = p.getBool(Projective::kCull) && mBlurRadius == 0;
    const uint32_t layers = uint32_t(std::max<size_t>(1, mPlan.viewProj.size()));
    createTextures(ctx.context, layers);
    createDescriptors(ctx.context, layers);
    mTextureLayout = createScenePipelineLayout(ctx, {mSets.layout(kTextureSet)});
    mLightingLayout = createScenePipelineLayout(ctx, {mSets.layout(kLightingSet)});
    buildPipelines(ctx);
    // As ProjectiveGL: point-sampled weights and a lit outside (the texture's white border), one channel.
    VulkanSeparableBlur::Settings blur{.width = mPlan.viewProj.empty() ? 0 : mBlurRadius,
                                       .resolution = mResolution,
                                       .format = VK_FORMAT_R8_UNORM,
                                       .pointSampled = true,
                                       .outsideOne = true};
    const std::string blurKey = mBlur.compile(ctx.context, ctx.shaders, ctx.pipelines, blur, mArray);
    if (!blurKey.empty()) setPermutationKey(permutationKey() + "|" + blurKey);
}

void ProjectiveVulkan::renderTexture(VulkanFrameContext& ctx) {
    mCulled = 0;
    const glm::mat4 camera = ctx.proj * ctx.view;
    VkClearValue white{};
    white.color = {{1.0f, 1.0f, 1.0f, 1.0f}};
    const VkDescriptorSet set = mSets.set(kTextureSet);
    for (size_t i = 0; i < mPlan.viewProj.size(); ++i) {
        if (!mPlan.castsShadows[i]) continue;
        size_t kept = mCulling.count(DrawSet::Casters);
        if (mCull) { // a caster whose shadow misses the view puts no texel where a visible receiver looks
            kept = mCulling.cullShadows(ctx.scene.lights[i], mPlan.receivers, camera, mKeep);
            mCulled += mCulling.count(DrawSet::Casters) - kept;
        }
        VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        begin.renderPass = mTexturePass;
        begin.framebuffer = mFramebuffers[i];
        begin.renderArea.extent = {uint32_t(mResolution), uint32_t(mResolution)};
        begin.clearValueCount = 1;
        begin.pClearValues = &white;
        vkCmdBeginRenderPass(ctx.cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
        if (kept) {
            const VkViewport viewport{0.0f, 0.0f, float(mResolution), float(mResolution), 0.0f, 1.0f};
            const VkRect2D scissor{{0, 0}, {uint32_t(mResolution), uint32_t(mResolution)}};
            vkCmdSetViewport(ctx.cmd, 0, 1, &viewport);
            vkCmdSetScissor(ctx.cmd, 0, 1, &scissor);
            vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mTexturePipeline);
            const uint32_t offset = mStride * uint32_t(i);
            vkCmdBindDescriptorSets(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mTextureLayout, 1, 1, &set, 1,
                                    &offset);
            // A silhouette with no depth test: a closed caster's front faces cover what it covers
            // (scenes/BackFaceCulling.h). The projector's clip space is GL's, unflipped (depthFromGl).
            ctx.submitter.drawCulled(ctx.cmd, mTextureLayout, DrawSet::Casters, {mPlan.viewProj[i], false},
                                     false, mCull ? InstanceMask(mKeep) : InstanceMask{});
        }
        vkCmdEndRenderPass(ctx.cmd);
    }
}

int ProjectiveVulkan::renderBlur(VulkanFrameContext& ctx) {
    // Two passes of resolution^2 texels per layer that casts, as GL's SeparableBlur::Work::passes.
    const double perPass = double(mResolution) * mResolution;
    return int(std::lround(mBlur.apply(ctx.cmd, mPlan.castsShadows) / perPass));
}

void ProjectiveVulkan::renderLighting(VulkanFrameContext& ctx) {
    if (mPlan.viewProj.empty()) { // nothing casts: every instance lit
        drawLitScene(ctx, mLit, mLightingLayout);
        return;
    }
    // Casters fully lit (no self-shadowing: the texture cannot tell a caster's lit side from its
    // shadowed one), then the receivers with the projected textures.
    VkCommandBuffer cmd = ctx.cmd;
    ctx.targets.beginPass(cmd);
    ctx.frame.bind(cmd, mLightingLayout, ctx.frameOffset);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLit.get(ctx.targets));
    const CullView camera = cameraCullView(ctx);
    ctx.submitter.drawCulled(cmd, mLightingLayout, DrawSet::Casters, camera, true);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mProjective.get(ctx.targets));
    const VkDescriptorSet set = mSets.set(kLightingSet);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLightingLayout, 1, 1, &set, 0, nullptr);
    ctx.submitter.drawCulled(cmd, mLightingLayout, DrawSet::NonCasters, camera, true);
    vkCmdEndRenderPass(cmd);
}

void ProjectiveVulkan::execute(VulkanFrameContext& ctx) {
    ctx.submitter.resetStats();
    int blurPasses = 0;
    if (mPlan.noProjector) {
        ctx.passes.skip("texture", mPlan.noProjector);
        ctx.passes.skip("blur", mPlan.noProjector);
    } else {
        ctx.passes.begin("texture");
        renderTexture(ctx);
        if (mBlurRadius > 0) {
            ctx.passes.begin("blur");
            blurPasses = renderBlur(ctx);
        } else {
            ctx.passes.skip("blur", "blur 0");
        }
    }
    ctx.passes.begin("lighting");
    renderLighting(ctx);
    mCounters = Projective::counters(ctx.submitter.stats(), ctx.scene, mResolution, mPlan.castsShadows,
                                     blurPasses, mPlan.clamped, mCulled);
}

} // namespace sb
