#include "vk/LayerPasses.h"

#include <string>

#include "vk/VulkanContext.h"

namespace sb {

VkRenderPass LayerPasses::colourPass(VkDevice device, VkFormat format, VkAttachmentLoadOp load,
                                     const char* what) {
    VkAttachmentDescription a{};
    a.format = format;
    a.samples = VK_SAMPLE_COUNT_1_BIT;
    a.loadOp = load;
    a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    a.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    a.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    a.finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription sub{};
    sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    sub.colorAttachmentCount = 1;
    sub.pColorAttachments = &ref;
    // Before: a previous pass sampled the layer (write after read) or wrote it (write after write).
    // After: the next pass's fragment shader reads what this one wrote.
    VkSubpassDependency deps[2]{};
    deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    deps[0].dstSubpass = 0;
    deps[0].srcStageMask =
        VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[0].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[1].srcSubpass = 0;
    deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    deps[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    deps[1].dstStageMask = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    deps[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    deps[1].dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = 1;
    info.pAttachments = &a;
    info.subpassCount = 1;
    info.pSubpasses = &sub;
    info.dependencyCount = 2;
    info.pDependencies = deps;
    VkRenderPass pass = VK_NULL_HANDLE;
    VulkanContext::check(vkCreateRenderPass(device, &info, nullptr, &pass),
                         ("vkCreateRenderPass (" + std::string(what) + ")").c_str());
    return pass;
}

VkFramebuffer LayerPasses::framebuffer(VkDevice device, VkRenderPass pass, VkImageView view, uint32_t size,
                                       uint32_t layers, const char* what) {
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = pass;
    info.attachmentCount = 1;
    info.pAttachments = &view;
    info.width = info.height = size;
    info.layers = layers;
    VkFramebuffer fb = VK_NULL_HANDLE;
    VulkanContext::check(vkCreateFramebuffer(device, &info, nullptr, &fb),
                         ("vkCreateFramebuffer (" + std::string(what) + ")").c_str());
    return fb;
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

} // namespace sb
