#pragma once
// The depth maps of the shadow-map family on Vulkan (techniques/shadowmap/DepthLayers.h on GL), put
// together by VulkanDepthMapSet (the moment maps take the format): the map format, an image of layers
// cleared to "lit", the render pass a depth layer is drawn with (its framebuffers are vk/LayerPasses'),
// and the sampler the lighting pass compares through. Below the technique folders, with
// VulkanDepthMapSet, so that a technique outside the family renders its light depth maps with the same
// pieces.
#include <cstdint>

#include <vulkan/vulkan.h>

#include "vk/VulkanImage.h"

namespace sb {

class VulkanContext;

class VulkanDepthMaps {
public:
    /// X8_D24 where it can be attached, sampled and filtered (GL's DEPTH_COMPONENT24: the same depth
    /// quantum, so glPolygonOffset's constant means the same bias), else D32_SFLOAT.
    static VkFormat format(VkPhysicalDevice physical);
    /// `layers` layers of size^2 (a cube array when `cube`), every layer cleared to the far plane and left
    /// in the layout the lighting pass samples: layers a frame does not render (a light that casts no
    /// shadow, a face nothing reaches) are read as they are.
    static VulkanImage image(VulkanContext& context, VkFormat format, uint32_t size, uint32_t layers,
                             bool cube);
    /// One depth attachment cleared at the start and left DEPTH_STENCIL_READ_ONLY for the lighting pass,
    /// with the dependencies on the previous frame's reads and this frame's. The caller owns it.
    static VkRenderPass renderPass(VkDevice device, VkFormat format);
    /// The lighting pass's sampler: with `compare`, LEQUAL depth compare with LINEAR filtering of the four
    /// results (bilinear PCF); without, NEAREST depths the shader compares. Clamped at the edges.
    static VkSampler sampler(VkDevice device, bool compare);
};

} // namespace sb
