#pragma once
// The pieces of a pass that renders into the layers of an image array and of the pass that samples it:
// a render pass of one subpass over a colour and/or a depth attachment, the framebuffers of the layers,
// and the samplers such layers are read through. Used by the techniques' Vulkan forms (the blur of
// techniques/vulkan/VulkanSeparableBlur, projective's texture, the depth maps of
// techniques/vulkan/VulkanDepthMaps and VulkanDepthMapSet, the moment maps of
// techniques/shadowmap/VulkanMomentMaps).
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

namespace sb {

class VulkanImage;

class LayerPasses {
public:
    /// One attachment of a layer pass: single-sampled, UNDEFINED before the pass (its old contents are
    /// cleared or overwritten), stencil neither loaded nor kept.
    struct Attachment {
        VkFormat format = VK_FORMAT_UNDEFINED;
        VkAttachmentLoadOp load = VK_ATTACHMENT_LOAD_OP_CLEAR;
        VkAttachmentStoreOp store = VK_ATTACHMENT_STORE_OP_STORE;
        VkImageLayout finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    };
    /// One external dependency of the subpass: what `src` stages and accesses must finish before
    /// `dst` ones start.
    struct Barrier {
        VkPipelineStageFlags srcStages = 0, dstStages = 0;
        VkAccessFlags srcAccess = 0, dstAccess = 0;
    };
    /// A render pass of one subpass: `colour` (attachment 0) and/or `depth` (after it), `before` the
    /// dependency on what came before the pass, `after` the one of what comes after it.
    struct PassDesc {
        std::optional<Attachment> colour, depth;
        Barrier before, after;
    };
    /// The render pass of `desc`. `what` names it in an error. The caller owns it.
    static VkRenderPass renderPass(VkDevice device, const PassDesc& desc, const char* what);

    /// One colour attachment of `format` left SHADER_READ_ONLY for the pass that samples it; `load`
    /// CLEAR (the clear value given at begin) or DONT_CARE (overwritten whole). Dependencies: before,
    /// the previous reads (fragment shader) and writes of the layer; after, the next fragment shader's
    /// reads. `what` names it in an error. The caller owns it.
    static VkRenderPass colourPass(VkDevice device, VkFormat format, VkAttachmentLoadOp load,
                                   const char* what);

    /// A framebuffer of `views` (in `pass`'s attachment order) at `extent` and `layers` layers (a layered
    /// pass writes gl_Layer): a layer's, and any other target's (vk/VulkanTargets, the G-buffer of
    /// reference/VulkanGBufferRenderer, the occluder bake's). `what` names it in an error. The caller
    /// owns it.
    static VkFramebuffer framebuffer(VkDevice device, VkRenderPass pass, std::span<const VkImageView> views,
                                     VkExtent2D extent, uint32_t layers, const char* what);
    /// A framebuffer per layer of the first `count` layers of `array`, at its size: the layer's view,
    /// then `shared` where it is given (one depth attachment every layer's pass reuses). The layer views
    /// stay owned by `array`; the caller owns the framebuffers.
    static std::vector<VkFramebuffer> layerFramebuffers(VkDevice device, VkRenderPass pass,
                                                        VulkanImage& array, uint32_t count, const char* what,
                                                        VkImageView shared = VK_NULL_HANDLE);

    /// Records the start of `pass` (a depth-only pass: its one attachment the depth) over `framebuffer`,
    /// the depth cleared to `clearDepth` over all of `extent`, and sets the viewport (depth range [0, 1])
    /// and scissor to `extent`: what every depth pass over a whole layer (VulkanDepthMapSet's, the view
    /// depth pre-pass's) begins with. The caller records its draws and ends the pass.
    static void beginDepthPass(VkCommandBuffer cmd, VkRenderPass pass, VkFramebuffer framebuffer,
                               VkExtent2D extent, float clearDepth);

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
