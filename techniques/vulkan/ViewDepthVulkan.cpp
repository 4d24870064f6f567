#include "techniques/vulkan/ViewDepthVulkan.h"

#include <cstring>
#include <string>

#include "core/Error.h"
#include "techniques/ViewDepth.h"
#include "techniques/vulkan/ScenePass.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/LayerPasses.h"

namespace sb {

namespace {
constexpr VkFormat kFormat = VK_FORMAT_D32_SFLOAT; // GL_DEPTH_COMPONENT32F's stored floats
// Who reads the image after the pass, and whose reads the next frame's pass must wait for.
constexpr VkPipelineStageFlags kReaders =
    VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
constexpr VkPipelineStageFlags kDepthTests =
    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;

void requireFormat(const VulkanContext& context) {
    const VkFormatFeatureFlags need =
        VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
    VkFormatProperties p{};
    vkGetPhysicalDeviceFormatProperties(context.physicalDevice(), kFormat, &p);
    if ((p.optimalTilingFeatures & need) != need)
        throw Error("view depth pre-pass: the Vulkan device '" + context.info().name +
                        "' cannot attach and sample VK_FORMAT_D32_SFLOAT; run it with --api gl",
                    ExitCode::Unsupported);
}
} // namespace

ViewDepthVulkan::~ViewDepthVulkan() {
    release();
}

void ViewDepthVulkan::release() {
    if (!mDevice) return;
    vkDestroyPipelineLayout(mDevice, mLayout, nullptr);
    vkDestroyFramebuffer(mDevice, mFramebuffer, nullptr);
    vkDestroyRenderPass(mDevice, mPass, nullptr);
    mLayout = VK_NULL_HANDLE;
    mFramebuffer = VK_NULL_HANDLE;
    mPass = VK_NULL_HANDLE;
    mPipeline = VK_NULL_HANDLE;
    mSet = DescriptorSets();
    mLightingSet = DescriptorSets();
    mLightingBlock = VulkanBuffer();
    vkDestroySampler(mDevice, mSampler, nullptr);
    mSampler = VK_NULL_HANDLE;
    mMatrix = VulkanBuffer();
    mImage = VulkanImage();
    mDevice = VK_NULL_HANDLE;
}

void ViewDepthVulkan::compile(const VulkanCompileContext& ctx) {
    release();
    requireFormat(ctx.context);
    mDevice = ctx.context.device();
    mWidth = uint32_t(ctx.targets.width());
    mHeight = uint32_t(ctx.targets.height());
    VulkanImageDesc d;
    d.width = mWidth;
    d.height = mHeight;
    d.format = kFormat;
    // TRANSFER_SRC: the tests read it back (tests/CascadedSdsmVkTest.cpp); it costs nothing to allow.
    d.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
              VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    d.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    mImage = VulkanImage(ctx.context, d);
    // In the layout its readers' descriptors name from the start (its contents are the first frame's).
    ctx.context.submitNow([&](VkCommandBuffer cmd) {
        transitionImage(cmd, mImage.image(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
    });
    LayerPasses::PassDesc pass;
    pass.depth = LayerPasses::Attachment{kFormat, VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_STORE,
                                         VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL};
    // Before: the previous frame's readers (write after read). After: this frame's readers.
    pass.before = {kReaders, kDepthTests, VK_ACCESS_SHADER_READ_BIT,
                   VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                       VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT};
    pass.after = {VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT, kReaders,
                  VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT};
    mPass = LayerPasses::renderPass(mDevice, pass, "view depth pre-pass");
    const VkImageView view = mImage.view();
    mFramebuffer =
        LayerPasses::framebuffer(mDevice, mPass, {&view, 1}, {mWidth, mHeight}, 1, "view depth pre-pass");

    mMatrix = VulkanBuffer(ctx.context, sizeof(glm::mat4), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    mSet = DescriptorSets(
        mDevice,
        {{DescriptorSets::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_VERTEX_BIT)}},
        "view depth pre-pass");
    mSet.writeBuffer(0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, mMatrix.buffer(), sizeof(glm::mat4));
    mLayout = createScenePipelineLayout(ctx, {mSet.layout(0)});
    std::string key = "view-depth|";
    // Depth only (no fragment stage: VulkanDepthMapSet::kDepthFragment says why), LESS with writes.
    GraphicsPipelineDesc desc =
        scenePipeline(ctx, "common/depth.vert", "", ctx.submitter.defines(), mLayout, key);
    desc.colourAttachments = 0;
    desc.renderPass = mPass;
    mPipeline = ctx.pipelines.get(key, desc);

    LayerPasses::Sampling nearest;
    nearest.filter = VK_FILTER_NEAREST;
    mSampler = LayerPasses::sampler(mDevice, nearest, "view depth pre-pass");
    using D = DescriptorSets;
    mLightingSet = DescriptorSets(
        mDevice,
        {{D::binding(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT),
          D::binding(1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT)}},
        "view depth pre-pass");
    mLightingSet.writeImage(0, 0, mSampler, mImage.view(), VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
    mLightingBlock = VulkanBuffer(ctx.context, sizeof(glm::vec4), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    mLightingSet.writeBuffer(0, 1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, mLightingBlock.buffer(),
                             sizeof(glm::vec4));
}

void ViewDepthVulkan::bindForLighting(VkCommandBuffer cmd, VkPipelineLayout layout,
                                      const glm::vec4& block) const {
    std::memcpy(mLightingBlock.map(), &block, sizeof block);
    const VkDescriptorSet set = mLightingSet.set(0);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, kLightingSet, 1, &set, 0, nullptr);
}

void ViewDepthVulkan::record(const VulkanFrameContext& ctx, VkCommandBuffer cmd) {
    // The frame block's clip space (y flipped, z to [0, w]): the targets' rows and GL's window depths.
    const glm::mat4 m = VulkanFrameBlock::clipFromGl() * ctx.proj * ctx.view;
    std::memcpy(mMatrix.map(), &m, sizeof m); // the previous frame's fence was waited for
    mProj = ctx.proj;
    LayerPasses::beginDepthPass(cmd, mPass, mFramebuffer, {mWidth, mHeight}, ViewDepth::kClear);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline);
    ctx.frame.bind(cmd, mLayout, ctx.frameOffset);
    const VkDescriptorSet set = mSet.set(0);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, 1, 1, &set, 0, nullptr);
    // Every instance: a non-receiver in front of a receiver hides its samples as well.
    ctx.submitter.drawCulled(cmd, mLayout, DrawSet::All, cameraCullView(ctx), true);
    vkCmdEndRenderPass(cmd);
}

} // namespace sb
