#include "techniques/vulkan/VulkanDepthMaps.h"

#include "vk/LayerPasses.h"
#include "vk/VulkanContext.h"

namespace sb {

VkFormat VulkanDepthMaps::format(VkPhysicalDevice physical) {
    const VkFormatFeatureFlags need = VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                      VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT |
                                      VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
    VkFormatProperties p{};
    vkGetPhysicalDeviceFormatProperties(physical, VK_FORMAT_X8_D24_UNORM_PACK32, &p);
    return (p.optimalTilingFeatures & need) == need ? VK_FORMAT_X8_D24_UNORM_PACK32 : VK_FORMAT_D32_SFLOAT;
}

VulkanImage VulkanDepthMaps::image(VulkanContext& context, VkFormat format, uint32_t size, uint32_t layers,
                                   bool cube) {
    VulkanImageDesc d;
    d.width = d.height = size;
    d.layers = layers;
    d.format = format;
    d.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
              VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    d.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    d.viewType = cube ? VK_IMAGE_VIEW_TYPE_CUBE_ARRAY : VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    d.cube = cube;
    VulkanImage image(context, d);
    context.submitNow([&](VkCommandBuffer cmd) {
        transitionImage(cmd, image.image(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, layers);
        VkClearDepthStencilValue one{1.0f, 0};
        VkImageSubresourceRange range{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, layers};
        vkCmdClearDepthStencilImage(cmd, image.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &one, 1,
                                    &range);
        transitionImage(cmd, image.image(), VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                        VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, layers);
    });
    return image;
}

VkRenderPass VulkanDepthMaps::renderPass(VkDevice device, VkFormat format) {
    LayerPasses::PassDesc desc;
    desc.depth = LayerPasses::Attachment{format, VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_STORE,
                                         VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL};
    // Before: the previous frame's lighting pass read the map (write after read). After: this frame's
    // lighting pass reads what the depth tests wrote.
    desc.before = {VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                   VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                   VK_ACCESS_SHADER_READ_BIT,
                   VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                       VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT};
    desc.after = {VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                  VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT};
    return LayerPasses::renderPass(device, desc, "shadow map");
}

VkSampler VulkanDepthMaps::sampler(VkDevice device, bool compare) {
    LayerPasses::Sampling s;
    s.filter = compare ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
    s.compare = compare;
    return LayerPasses::sampler(device, s, "shadow map");
}

} // namespace sb
