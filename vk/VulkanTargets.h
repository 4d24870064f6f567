#pragma once
// The frame targets on Vulkan, the same three as gl/FrameTargets: colour (R8G8B8A8_UNORM, attachment 0),
// visibility (R16G16B16A16_SFLOAT, attachment 1: channel i = light i, 1 lit, 0 shadowed) and
// depth-stencil (VulkanContext::depthStencilFormat, attachment 2 or 1).
//
// Render passes. Every pass a technique records into the targets begins one of the render passes here
// with loadOp LOAD (the harness cleared the targets before the technique runs, as glClear does on GL),
// the attachments in their attachment-optimal layouts before and after. Two variants, with and without
// the visibility attachment: timed frames render what an application would, without the harness's
// instrument (gl/FrameTargets.h, setVisibilityOutput), so their pipelines are built against the
// variant without it. A pipeline is built against renderPass(visibility) and records only inside it.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/VulkanImage.h"

namespace sb {

class VulkanContext;

class VulkanTargets {
public:
    VulkanTargets(VulkanContext& context, int width, int height);
    ~VulkanTargets();
    VulkanTargets(const VulkanTargets&) = delete;
    VulkanTargets& operator=(const VulkanTargets&) = delete;

    int width() const { return mWidth; }
    int height() const { return mHeight; }

    /// Whether the frames now recorded write the visibility attachment (default on; see above).
    void setVisibilityOutput(bool on) { mVisibilityOn = on; }
    bool visibilityOutput() const { return mVisibilityOn; }
    /// The LOAD render pass of the current variant and its framebuffer.
    VkRenderPass renderPass() const { return renderPass(mVisibilityOn); }
    VkRenderPass renderPass(bool visibility) const { return mLoadPass[visibility ? 1 : 0]; }
    VkFramebuffer framebuffer() const { return mFramebuffer[mVisibilityOn ? 1 : 0]; }
    /// Colour attachments of the current variant (1 or 2): pipelines size their blend state by it.
    uint32_t colourAttachments() const { return mVisibilityOn ? 2u : 1u; }
    uint32_t colourAttachments(bool visibility) const { return visibility ? 2u : 1u; }

    /// Records the clear of a frame: colour to (r, g, b, 1), visibility to 1 (lit), depth to 1, stencil
    /// to 0, leaving every attachment in its attachment-optimal layout (a render pass with loadOp CLEAR
    /// and no draws, the current variant's).
    void recordClear(VkCommandBuffer cmd, float r, float g, float b) const;
    /// Begins the current variant's LOAD pass over the whole target (viewport and scissor set to it).
    void beginPass(VkCommandBuffer cmd) const;

    /// Read-backs after the frame's fence (synchronous; for screenshots and tests, never inside timed
    /// frames). Rows bottom-up like gl/FrameTargets (row 0 is the bottom of the image), so the two APIs'
    /// images compare pixel for pixel; the projection's y flip is the technique's.
    std::vector<unsigned char> readColorRGBA8();
    std::vector<float> readVisibilityRGBA32F(); ///< 4 floats per pixel (from half floats)
    std::vector<float> readDepth();             ///< depth aspect as floats in [0, 1]

private:
    VkRenderPass createPass(bool visibility, bool clear) const;
    void destroy(); ///< the passes and framebuffers (the destructor, and a constructor that throws)
    /// Copies one aspect of `image` to a host buffer, returning its bytes, rows flipped bottom-up.
    std::vector<unsigned char> readImage(VulkanImage& image, VkImageAspectFlags aspect, VkImageLayout layout,
                                         uint32_t texelBytes);

    VulkanContext& mContext;
    int mWidth, mHeight;
    bool mVisibilityOn = true;
    VulkanImage mColour, mVisibility, mDepth;
    VkRenderPass mLoadPass[2]{}, mClearPass[2]{};
    VkFramebuffer mFramebuffer[2]{};
};

} // namespace sb
