#include "reference/VulkanGBufferRenderer.h"

#include <cstring>

#include "techniques/vulkan/VulkanFrameBlock.h"
#include "techniques/vulkan/VulkanSubmitter.h"
#include "vk/GraphicsPipeline.h"
#include "vk/LayerPasses.h"
#include "vk/ShaderModuleCache.h"
#include "vk/VulkanContext.h"

namespace sb {

namespace {
constexpr VkFormat kPositionFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkFormat kPrimitiveFormat = VK_FORMAT_R32_UINT;
constexpr VkImageAspectFlags kDepthStencil = VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;

VulkanImage colourImage(VulkanContext& context, int width, int height, VkFormat format) {
    VulkanImageDesc d;
    d.width = uint32_t(width);
    d.height = uint32_t(height);
    d.format = format;
    d.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    return VulkanImage(context, d);
}

/// Copies `image` (in TRANSFER_SRC_OPTIMAL) into `host`, whose rows come out top-down (Vulkan's order).
void recordCopy(VkCommandBuffer cmd, const VulkanImage& image, const VulkanBuffer& host, int width,
                int height) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {uint32_t(width), uint32_t(height), 1};
    vkCmdCopyImageToBuffer(cmd, image.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, host.buffer(), 1,
                           &region);
}

/// `rows` rows of `rowBytes` from `src` (top-down) into `dst` bottom-up, as GL reads them.
void copyRowsFlipped(void* dst, const void* src, size_t rowBytes, int rows) {
    auto* out = static_cast<unsigned char*>(dst);
    const auto* in = static_cast<const unsigned char*>(src);
    for (int row = 0; row < rows; ++row)
        std::memcpy(out + size_t(row) * rowBytes, in + size_t(rows - 1 - row) * rowBytes, rowBytes);
}
} // namespace

VulkanGBufferRenderer::VulkanGBufferRenderer(VulkanContext& context, ShaderModuleCache& shaders,
                                             const VulkanSubmitter& submitter, VulkanFrameBlock& frame,
                                             int width, int height)
    : mContext(context), mFrame(frame), mWidth(width), mHeight(height) {
    mPosition = colourImage(context, width, height, kPositionFormat);
    mPrimitive = colourImage(context, width, height, kPrimitiveFormat);
    VulkanImageDesc depth;
    depth.width = uint32_t(width);
    depth.height = uint32_t(height);
    depth.format = context.depthStencilFormat(); // the frame targets': the same depth test
    depth.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    depth.aspect = kDepthStencil;
    mDepth = VulkanImage(context, depth);
    const VkDeviceSize pixels = VkDeviceSize(width) * VkDeviceSize(height);
    mPositionHost = VulkanBuffer(context, pixels * 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    mPrimitiveHost = VulkanBuffer(context, pixels * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    try {
        createRenderPass();
        createPipeline(shaders, submitter);
    } catch (...) {
        destroy();
        throw;
    }
}

VulkanGBufferRenderer::~VulkanGBufferRenderer() {
    destroy();
}

void VulkanGBufferRenderer::destroy() {
    VkDevice device = mContext.device();
    if (mPipeline) vkDestroyPipeline(device, mPipeline, nullptr);
    if (mLayout) vkDestroyPipelineLayout(device, mLayout, nullptr);
    if (mFramebuffer) vkDestroyFramebuffer(device, mFramebuffer, nullptr);
    if (mPass) vkDestroyRenderPass(device, mPass, nullptr);
    mPipeline = VK_NULL_HANDLE;
    mLayout = VK_NULL_HANDLE;
    mFramebuffer = VK_NULL_HANDLE;
    mPass = VK_NULL_HANDLE;
}

void VulkanGBufferRenderer::createRenderPass() {
    // Every attachment cleared (position and id 0: no geometry; depth 1); the colour images end ready
    // to be copied out, the depth is not kept.
    auto attachment = [](VkFormat format, VkImageLayout finalLayout, VkAttachmentStoreOp store) {
        VkAttachmentDescription a{};
        a.format = format;
        a.samples = VK_SAMPLE_COUNT_1_BIT;
        a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        a.storeOp = store;
        a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        a.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        a.finalLayout = finalLayout;
        return a;
    };
    const VkAttachmentDescription attachments[3] = {
        attachment(kPositionFormat, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ATTACHMENT_STORE_OP_STORE),
        attachment(kPrimitiveFormat, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ATTACHMENT_STORE_OP_STORE),
        attachment(mContext.depthStencilFormat(), VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                   VK_ATTACHMENT_STORE_OP_DONT_CARE)};
    const VkAttachmentReference colours[2] = {{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
                                              {1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}};
    const VkAttachmentReference depthRef{2, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 2;
    subpass.pColorAttachments = colours;
    subpass.pDepthStencilAttachment = &depthRef;

    constexpr VkPipelineStageFlags kAttachmentStages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                       VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                       VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    constexpr VkAccessFlags kAttachmentWrites =
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    VkSubpassDependency dependencies[2]{};
    // The previous render's copies read the images this pass writes again.
    dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[0].dstSubpass = 0;
    dependencies[0].srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT | kAttachmentStages;
    dependencies[0].srcAccessMask = kAttachmentWrites;
    dependencies[0].dstStageMask = kAttachmentStages;
    dependencies[0].dstAccessMask =
        kAttachmentWrites | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
    // The copies after the pass read what it wrote.
    dependencies[1].srcSubpass = 0;
    dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[1].srcStageMask = kAttachmentStages;
    dependencies[1].srcAccessMask = kAttachmentWrites;
    dependencies[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dependencies[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;

    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = 3;
    info.pAttachments = attachments;
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 2;
    info.pDependencies = dependencies;
    VulkanContext::check(vkCreateRenderPass(mContext.device(), &info, nullptr, &mPass),
                         "vkCreateRenderPass (G-buffer)");

    const VkImageView views[3] = {mPosition.view(), mPrimitive.view(), mDepth.view()};
    mFramebuffer = LayerPasses::framebuffer(mContext.device(), mPass, views,
                                            {uint32_t(mWidth), uint32_t(mHeight)}, 1, "G-buffer");
}

void VulkanGBufferRenderer::createPipeline(ShaderModuleCache& shaders, const VulkanSubmitter& submitter) {
    mLayout = createPipelineLayout(mContext, {mFrame.setLayout()}, sizeof(VulkanPush));
    const ShaderModules modules = shaders.get(
        ShaderSources{"reference/gbuffer.vert", "reference/gbuffer.frag", ""}, submitter.defines());
    // A lit pass's state (techniques/vulkan/ScenePass.h): GraphicsPipelineDesc's defaults are GL's.
    GraphicsPipelineDesc d;
    d.vertex = modules.vertex;
    d.fragment = modules.fragment;
    d.bindings = submitter.bindings();
    d.attributes = submitter.attributes();
    d.colourAttachments = 2;
    d.renderPass = mPass;
    d.layout = mLayout;
    mPipeline = createGraphicsPipeline(mContext, d);
}

GBuffer VulkanGBufferRenderer::render(VulkanSubmitter& submitter, uint32_t frameOffset) {
    // The caller's counters keep running; this render's share is the difference (as on GL).
    const SubmitStats before = submitter.stats();
    mContext.submitNow([&](VkCommandBuffer cmd) {
        VkClearValue clears[3]{};
        clears[0].color = {{0.0f, 0.0f, 0.0f, 0.0f}};
        clears[1].color.uint32[0] = 0u;
        clears[2].depthStencil = {1.0f, 0};
        const VkExtent2D extent{uint32_t(mWidth), uint32_t(mHeight)};
        VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        begin.renderPass = mPass;
        begin.framebuffer = mFramebuffer;
        begin.renderArea = {{0, 0}, extent};
        begin.clearValueCount = 3;
        begin.pClearValues = clears;
        vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
        // As VulkanTargets::beginPass: no viewport flip, the frame block's projection flips y.
        const VkViewport viewport{0.0f, 0.0f, float(mWidth), float(mHeight), 0.0f, 1.0f};
        const VkRect2D scissor{{0, 0}, extent};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline);
        mFrame.bind(cmd, mLayout, frameOffset);
        submitter.draw(cmd, mLayout, DrawSet::All);
        vkCmdEndRenderPass(cmd);
        recordCopy(cmd, mPosition, mPositionHost, mWidth, mHeight);
        recordCopy(cmd, mPrimitive, mPrimitiveHost, mWidth, mHeight);
        VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost,
                             0, nullptr, 0, nullptr);
    });
    mStats = submitter.stats() - before;
    GBuffer g;
    g.width = mWidth;
    g.height = mHeight;
    g.position.resize(g.size());
    g.primitive.resize(g.size());
    copyRowsFlipped(g.position.data(), mPositionHost.map(), size_t(mWidth) * sizeof(glm::vec4), mHeight);
    copyRowsFlipped(g.primitive.data(), mPrimitiveHost.map(), size_t(mWidth) * sizeof(uint32_t), mHeight);
    g.splitBackFaces();
    return g;
}

} // namespace sb
