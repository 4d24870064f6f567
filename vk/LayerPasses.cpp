#include "vk/LayerPasses.h"

#include <string>

#include "vk/VulkanContext.h"
#include "vk/VulkanImage.h"

namespace sb {

namespace {

VkAttachmentDescription description(const LayerPasses::Attachment& a) {
    VkAttachmentDescription d{};
    d.format = a.format;
    d.samples = VK_SAMPLE_COUNT_1_BIT;
    d.loadOp = a.load;
    d.storeOp = a.store;
    d.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    d.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    d.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    d.finalLayout = a.finalLayout;
    return d;
}

VkSubpassDependency dependency(uint32_t src, uint32_t dst, const LayerPasses::Barrier& b) {
    VkSubpassDependency d{};
    d.srcSubpass = src;
    d.dstSubpass = dst;
    d.srcStageMask = b.srcStages;
    d.dstStageMask = b.dstStages;
    d.srcAccessMask = b.srcAccess;
    d.dstAccessMask = b.dstAccess;
    return d;
}

} // namespace

VkRenderPass LayerPasses::renderPass(VkDevice device, const PassDesc& desc, const char* what) {
    std::vector<VkAttachmentDescription> attachments;
    VkSubpassDescription sub{};
    sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    const VkAttachmentReference colourRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    if (desc.colour) {
        attachments.push_back(description(*desc.colour));
        sub.colorAttachmentCount = 1;
        sub.pColorAttachments = &colourRef;
    }
    const VkAttachmentReference depthRef{uint32_t(attachments.size()),
                                         VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    if (desc.depth) {
        attachments.push_back(description(*desc.depth));
        sub.pDepthStencilAttachment = &depthRef;
    }
    const VkSubpassDependency deps[2] = {dependency(VK_SUBPASS_EXTERNAL, 0, desc.before),
                                         dependency(0, VK_SUBPASS_EXTERNAL, desc.after)};
    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = uint32_t(attachments.size());
    info.pAttachments = attachments.data();
    info.subpassCount = 1;
    info.pSubpasses = &sub;
    info.dependencyCount = 2;
    info.pDependencies = deps;
    VkRenderPass pass = VK_NULL_HANDLE;
    VulkanContext::check(vkCreateRenderPass(device, &info, nullptr, &pass),
                         ("vkCreateRenderPass (" + std::string(what) + ")").c_str());
    return pass;
}

VkRenderPass LayerPasses::colourPass(VkDevice device, VkFormat format, VkAttachmentLoadOp load,
                                     const char* what) {
    PassDesc desc;
    desc.colour =
        Attachment{format, load, VK_ATTACHMENT_STORE_OP_STORE, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    // Before: a previous pass sampled the layer (write after read) or wrote it (write after write).
    desc.before = {VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                   VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                   VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT};
    // After: the next pass's fragment shader reads what this one wrote.
    desc.after = {VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                  VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT};
    return renderPass(device, desc, what);
}

VkFramebuffer LayerPasses::framebuffer(VkDevice device, VkRenderPass pass, std::span<const VkImageView> views,
                                       VkExtent2D extent, uint32_t layers, const char* what) {
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = pass;
    info.attachmentCount = uint32_t(views.size());
    info.pAttachments = views.data();
    info.width = extent.width;
    info.height = extent.height;
    info.layers = layers;
    VkFramebuffer fb = VK_NULL_HANDLE;
    VulkanContext::check(vkCreateFramebuffer(device, &info, nullptr, &fb),
                         ("vkCreateFramebuffer (" + std::string(what) + ")").c_str());
    return fb;
}

std::vector<VkFramebuffer> LayerPasses::layerFramebuffers(VkDevice device, VkRenderPass pass,
                                                          VulkanImage& array, uint32_t count,
                                                          const char* what, VkImageView shared) {
    const VkExtent2D extent{array.desc().width, array.desc().height};
    std::vector<VkFramebuffer> framebuffers;
    try {
        for (uint32_t i = 0; i < count; ++i) {
            const VkImageView views[2] = {array.layerView(i), shared};
            framebuffers.push_back(framebuffer(device, pass, {views, shared ? 2u : 1u}, extent, 1, what));
        }
    } catch (...) { // none left behind when a later one fails
        for (VkFramebuffer fb : framebuffers) vkDestroyFramebuffer(device, fb, nullptr);
        throw;
    }
    return framebuffers;
}

VkSampler LayerPasses::sampler(VkDevice device, const Sampling& sampling, const char* what) {
    VkSamplerCreateInfo s{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    s.magFilter = s.minFilter = sampling.filter;
    s.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    s.addressModeU = s.addressModeV = s.addressModeW = sampling.whiteBorder
                                                           ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER
                                                           : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    if (sampling.whiteBorder) s.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
    s.compareEnable = sampling.compare ? VK_TRUE : VK_FALSE;
    s.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    s.maxLod = 0.0f;
    VkSampler sampler = VK_NULL_HANDLE;
    VulkanContext::check(vkCreateSampler(device, &s, nullptr, &sampler),
                         ("vkCreateSampler (" + std::string(what) + ")").c_str());
    return sampler;
}

void LayerPasses::beginDepthPass(VkCommandBuffer cmd, VkRenderPass pass, VkFramebuffer framebuffer,
                                 VkExtent2D extent, float clearDepth) {
    VkClearValue clear{};
    clear.depthStencil = {clearDepth, 0};
    VkRenderPassBeginInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    info.renderPass = pass;
    info.framebuffer = framebuffer;
    info.renderArea.extent = extent;
    info.clearValueCount = 1;
    info.pClearValues = &clear;
    vkCmdBeginRenderPass(cmd, &info, VK_SUBPASS_CONTENTS_INLINE);
    const VkViewport viewport{0.0f, 0.0f, float(extent.width), float(extent.height), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, extent};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

} // namespace sb
