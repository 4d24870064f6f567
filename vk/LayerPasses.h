#pragma once
// The pieces of a pass that renders into one layer of an image array and of the pass that samples it:
// a colour render pass over one attachment, a framebuffer of one view, and the samplers such layers are
// read through. Used by the techniques' Vulkan forms (the blur of techniques/vulkan/VulkanSeparableBlur,
// projective's texture, the depth maps of techniques/vulkan/VulkanDepthMaps).
#include <cstdint>

#include <vulkan/vulkan.h>

namespace sb {

class LayerPasses {
public:
    /// One colour attachment of `format` left SHADER_READ_ONLY for the pass that samples it; `load`
    /// CLEAR (the clear value given at begin) or DONT_CARE (overwritten whole). Dependencies: before,
    /// the previous reads (fragment shader) and writes of the layer; after, the next fragment shader's
    /// reads. `what` names it in an error. The caller owns it.
    static VkRenderPass colourPass(VkDevice device, VkFormat format, VkAttachmentLoadOp load,
                                   const char* what);
    /// A framebuffer of `view` (`layers` layers: a layered pass writes gl_Layer) at size^2 for `pass`.
    static VkFramebuffer framebuffer(VkDevice device, VkRenderPass pass, VkImageView view, uint32_t size,
                                     uint32_t layers, const char* what);
    /// What a sampler of a layer does at its edges and between texels.
    struct Sampling {
        VkFilter filter = VK_FILTER_LINEAR;
        /// CLAMP_TO_EDGE, or CLAMP_TO_BORDER with an opaque white border (depth 1, lit, "no occluder").
        bool whiteBorder = false;
        bool compare = false; ///< LEQUAL depth comparison
    };
    /// A sampler of mip level 0 only. The caller owns it.
    static VkSampler sampler(VkDevice device, const Sampling& sampling, const char* what);
};

} // namespace sb
