#include "vk/VulkanTargets.h"

#include <cmath>
#include <cstring>

#include "vk/LayerPasses.h"
#include "vk/VulkanBuffer.h"
#include "vk/VulkanContext.h"

namespace sb {
namespace {

constexpr VkFormat kColourFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkFormat kVisibilityFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
constexpr VkImageAspectFlags kDepthStencil = VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;

/// IEEE 754 binary16 to float, infinities and NaNs included.
float halfToFloat(uint16_t h) {
    const uint32_t sign = uint32_t(h & 0x8000u) << 16;
    const uint32_t exponent = (h >> 10) & 0x1Fu;
    const uint32_t mantissa = h & 0x3FFu;
    uint32_t bits;
    if (exponent == 0x1F) { // infinity or NaN (payload kept: half's quiet bit lands on float's)
        bits = sign | 0x7F800000u | (mantissa << 13);
    } else if (exponent != 0) { // normal
        bits = sign | ((exponent + 112u) << 23) | (mantissa << 13);
    } else if (mantissa == 0) { // signed zero
        bits = sign;
    } else { // subnormal: mantissa * 2^-24, exact in float
        const float magnitude = std::ldexp(float(mantissa), -24);
        return sign ? -magnitude : magnitude;
    }
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

} // namespace

VulkanTargets::VulkanTargets(VulkanContext& context, int width, int height)
    : mContext(context), mWidth(width), mHeight(height) {
    const uint32_t w = static_cast<uint32_t>(width), h = static_cast<uint32_t>(height);
    VulkanImageDesc colour;
    colour.width = w;
    colour.height = h;
    colour.format = kColourFormat;
    colour.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    mColour = VulkanImage(context, colour);
    VulkanImageDesc visibility = colour;
    visibility.format = kVisibilityFormat;
    mVisibility = VulkanImage(context, visibility);
    VulkanImageDesc depth = colour;
    depth.format = context.depthStencilFormat();
    depth.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    depth.aspect = kDepthStencil;
    mDepth = VulkanImage(context, depth);

    try {
        for (int v = 0; v < 2; ++v) {
            mLoadPass[v] = createPass(v == 1, false);
            mClearPass[v] = createPass(v == 1, true);
            std::vector<VkImageView> views{mColour.view()};
            if (v == 1) views.push_back(mVisibility.view());
            views.push_back(mDepth.view());
            // mLoadPass[v] is compatible with mClearPass[v]: the same formats and samples.
            mFramebuffer[v] =
                LayerPasses::framebuffer(context.device(), mLoadPass[v], views, {w, h}, 1, "targets");
        }
        // Every attachment lives in its attachment-optimal layout from here on (contents undefined until
        // the first recordClear), so a LOAD pass or a read-back is never given an UNDEFINED image.
        context.submitNow([&](VkCommandBuffer cmd) {
            transitionImage(cmd, mColour.image(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
            transitionImage(cmd, mVisibility.image(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
            transitionImage(cmd, mDepth.image(), kDepthStencil, VK_IMAGE_LAYOUT_UNDEFINED,
                            VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
        });
    } catch (...) {
        destroy();
        throw;
    }
}

VulkanTargets::~VulkanTargets() {
    destroy();
}

void VulkanTargets::destroy() {
    VkDevice device = mContext.device();
    for (int v = 0; v < 2; ++v) {
        if (mFramebuffer[v]) vkDestroyFramebuffer(device, mFramebuffer[v], nullptr);
        if (mLoadPass[v]) vkDestroyRenderPass(device, mLoadPass[v], nullptr);
        if (mClearPass[v]) vkDestroyRenderPass(device, mClearPass[v], nullptr);
        mFramebuffer[v] = VK_NULL_HANDLE;
        mLoadPass[v] = mClearPass[v] = VK_NULL_HANDLE;
    }
}

VkRenderPass VulkanTargets::createPass(bool visibility, bool clear) const {
    const VkAttachmentLoadOp load = clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    auto attachment = [&](VkFormat format, VkImageLayout layout) {
        VkAttachmentDescription a{};
        a.format = format;
        a.samples = VK_SAMPLE_COUNT_1_BIT;
        a.loadOp = load;
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        a.stencilLoadOp = load;
        a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_STORE;
        a.initialLayout = clear ? VK_IMAGE_LAYOUT_UNDEFINED : layout;
        a.finalLayout = layout;
        return a;
    };
    std::vector<VkAttachmentDescription> attachments{
        attachment(kColourFormat, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL)};
    std::vector<VkAttachmentReference> colours{{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL}};
    if (visibility) {
        attachments.push_back(attachment(kVisibilityFormat, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL));
        colours.push_back({1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
    }
    const VkAttachmentReference depth{static_cast<uint32_t>(attachments.size()),
                                      VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    attachments.push_back(
        attachment(mContext.depthStencilFormat(), VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL));

    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = static_cast<uint32_t>(colours.size());
    subpass.pColorAttachments = colours.data();
    subpass.pDepthStencilAttachment = &depth;

    // The passes before and after: other render passes into these targets (attachment reads and writes),
    // fragment shaders sampling what a pass wrote (a shadow map), and transfers (read-backs, copies).
    constexpr VkPipelineStageFlags kAttachmentStages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                       VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                       VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    constexpr VkAccessFlags kAttachmentAccess =
        VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
        VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    constexpr VkPipelineStageFlags kAround =
        kAttachmentStages | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT;
    VkSubpassDependency dependencies[2]{};
    dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[0].dstSubpass = 0;
    dependencies[0].srcStageMask = kAround;
    dependencies[0].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                                    VK_ACCESS_TRANSFER_WRITE_BIT;
    dependencies[0].dstStageMask = kAttachmentStages | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    dependencies[0].dstAccessMask = kAttachmentAccess | VK_ACCESS_SHADER_READ_BIT;
    dependencies[1].srcSubpass = 0;
    dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[1].srcStageMask = kAttachmentStages;
    dependencies[1].srcAccessMask =
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    dependencies[1].dstStageMask = kAround;
    dependencies[1].dstAccessMask = kAttachmentAccess | VK_ACCESS_SHADER_READ_BIT |
                                    VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;

    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = static_cast<uint32_t>(attachments.size());
    info.pAttachments = attachments.data();
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = 2;
    info.pDependencies = dependencies;
    VkRenderPass pass = VK_NULL_HANDLE;
    VulkanContext::check(vkCreateRenderPass(mContext.device(), &info, nullptr, &pass), "vkCreateRenderPass");
    return pass;
}

void VulkanTargets::recordClear(VkCommandBuffer cmd, float r, float g, float b) const {
    const int v = mVisibilityOn ? 1 : 0;
    std::vector<VkClearValue> clears(1);
    clears[0].color = {{r, g, b, 1.0f}};
    if (mVisibilityOn) {
        clears.emplace_back();
        clears.back().color = {{1.0f, 1.0f, 1.0f, 1.0f}};
    }
    clears.emplace_back();
    clears.back().depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = mClearPass[v];
    begin.framebuffer = mFramebuffer[v];
    begin.renderArea = {{0, 0}, {static_cast<uint32_t>(mWidth), static_cast<uint32_t>(mHeight)}};
    begin.clearValueCount = static_cast<uint32_t>(clears.size());
    begin.pClearValues = clears.data();
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    vkCmdEndRenderPass(cmd);
}

void VulkanTargets::beginPass(VkCommandBuffer cmd) const {
    const int v = mVisibilityOn ? 1 : 0;
    const VkExtent2D extent{static_cast<uint32_t>(mWidth), static_cast<uint32_t>(mHeight)};
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = mLoadPass[v];
    begin.framebuffer = mFramebuffer[v];
    begin.renderArea = {{0, 0}, extent};
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    // No y flip: the techniques' projections flip y, so NDC y = -1 is image row 0 (the top in memory).
    const VkViewport viewport{0.0f, 0.0f, float(mWidth), float(mHeight), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

std::vector<unsigned char> VulkanTargets::readImage(VulkanImage& image, VkImageAspectFlags aspect,
                                                    VkImageLayout layout, uint32_t texelBytes) {
    const size_t rowBytes = size_t(mWidth) * texelBytes;
    const VkDeviceSize size = VkDeviceSize(rowBytes) * uint32_t(mHeight);
    VulkanBuffer host(mContext, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    const VkImageAspectFlags whole = image.desc().aspect; // both aspects of a depth-stencil image move
    mContext.submitNow([&](VkCommandBuffer cmd) {
        transitionImage(cmd, image.image(), whole, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
        VkBufferImageCopy region{};
        region.imageSubresource = {aspect, 0, 0, 1};
        region.imageExtent = {static_cast<uint32_t>(mWidth), static_cast<uint32_t>(mHeight), 1};
        vkCmdCopyImageToBuffer(cmd, image.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, host.buffer(), 1,
                               &region);
        transitionImage(cmd, image.image(), whole, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout);
        VkBufferMemoryBarrier toHost{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        toHost.srcQueueFamilyIndex = toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        toHost.buffer = host.buffer();
        toHost.size = VK_WHOLE_SIZE;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0, nullptr,
                             1, &toHost, 0, nullptr);
    });
    // Vulkan's row 0 is the top of the image; GL's (and this class's) is the bottom.
    std::vector<unsigned char> out(static_cast<size_t>(size));
    const auto* src = static_cast<const unsigned char*>(host.map());
    for (int row = 0; row < mHeight; ++row)
        std::memcpy(out.data() + size_t(row) * rowBytes, src + size_t(mHeight - 1 - row) * rowBytes,
                    rowBytes);
    return out;
}

std::vector<unsigned char> VulkanTargets::readColorRGBA8() {
    return readImage(mColour, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, 4);
}

std::vector<float> VulkanTargets::readVisibilityRGBA32F() {
    std::vector<unsigned char> bytes =
        readImage(mVisibility, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, 8);
    std::vector<float> out(bytes.size() / 2);
    for (size_t i = 0; i < out.size(); ++i) {
        uint16_t h;
        std::memcpy(&h, bytes.data() + 2 * i, 2);
        out[i] = halfToFloat(h);
    }
    return out;
}

std::vector<float> VulkanTargets::readDepth() {
    std::vector<unsigned char> bytes =
        readImage(mDepth, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, 4);
    const bool unorm24 = mDepth.desc().format == VK_FORMAT_D24_UNORM_S8_UINT;
    std::vector<float> out(bytes.size() / 4);
    for (size_t i = 0; i < out.size(); ++i) {
        if (unorm24) { // the depth aspect of D24S8 copies as 32-bit words, depth in the low 24 bits
            uint32_t word;
            std::memcpy(&word, bytes.data() + 4 * i, 4);
            out[i] = float(double(word & 0xFFFFFFu) / double(0xFFFFFFu));
        } else { // D32_SFLOAT_S8_UINT: its depth aspect copies as floats
            std::memcpy(&out[i], bytes.data() + 4 * i, 4);
        }
    }
    return out;
}

} // namespace sb
