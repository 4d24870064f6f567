#pragma once
// The G-buffer (reference/GBuffer.h) on Vulkan, as reference/GBufferRenderer.h renders it on GL: per
// pixel the world position and object id of the visible surface (RGBA32F), the triangle index within its
// draw with bit 31 set on a back face (R32_UINT), over a depth-stencil buffer of the frame targets'
// format. It draws through the run's own VulkanSubmitter with the frame block the lighting passes bind
// (the same view-projection, pixel shift included) and the pipeline state of a lit pass (depth LESS with
// writes, no culling, no bias, counter-clockwise front faces: techniques/vulkan/ScenePass.h), so every
// G-buffer sample is exactly one of the Vulkan lighting pass's pixels, and gl_FrontFacing is the
// decision that pass's shading made.
//
// The triangle index: Vulkan's PrimitiveId counts triangles within a draw and restarts with every
// instance of an instanced draw, like GL's; both Vulkan submission modes (retained: a draw per
// instance; instanced: an instance per kept instance) therefore number triangles per instance.
// Reading PrimitiveId in a fragment shader needs the device's geometryShader feature (VulkanContext
// enables it where offered; lavapipe offers it).
//
// Rendering is synchronous (VulkanContext::submitNow) and outside any frame: the harness has waited
// for its frame's fence, as a read-back of the frame targets does.
#include <cstdint>

#include <vulkan/vulkan.h>

#include "reference/GBuffer.h"
#include "techniques/Submission.h"
#include "vk/VulkanBuffer.h"
#include "vk/VulkanImage.h"

namespace sb {

class VulkanContext;
class ShaderModuleCache;
class VulkanSubmitter;
class VulkanFrameBlock;

class VulkanGBufferRenderer {
public:
    /// Images, render pass, framebuffer and pipeline for `submitter`'s vertex input and defines (the
    /// frame block must outlive the renderer). Throws sb::Error.
    VulkanGBufferRenderer(VulkanContext& context, ShaderModuleCache& shaders,
                          const VulkanSubmitter& submitter, VulkanFrameBlock& frame, int width, int height);
    ~VulkanGBufferRenderer();
    VulkanGBufferRenderer(const VulkanGBufferRenderer&) = delete;
    VulkanGBufferRenderer& operator=(const VulkanGBufferRenderer&) = delete;

    int width() const { return mWidth; }
    int height() const { return mHeight; }

    /// Draws DrawSet::All through `submitter` (the one the constructor was given, or one of the same
    /// mode) with shaders/reference/gbuffer.vert/.frag (VULKAN, plus the submitter's defines) and the
    /// frame block's slot `frameOffset`, then reads the G-buffer back (rows bottom-up, as the frame
    /// targets' read-backs). Submitted and waited for on its own command buffer, so it may run while a
    /// frame's command buffer is being recorded (the `reference` technique's gbuffer pass).
    GBuffer render(VulkanSubmitter& submitter, uint32_t frameOffset);
    /// Draw calls, triangles and instances of the last render().
    const SubmitStats& lastStats() const { return mStats; }

private:
    void createRenderPass();
    void createPipeline(ShaderModuleCache& shaders, const VulkanSubmitter& submitter);
    void destroy();

    VulkanContext& mContext;
    VulkanFrameBlock& mFrame;
    int mWidth, mHeight;
    VulkanImage mPosition, mPrimitive, mDepth;
    VulkanBuffer mPositionHost, mPrimitiveHost; ///< host-visible copies of the two colour images
    VkRenderPass mPass = VK_NULL_HANDLE;
    VkFramebuffer mFramebuffer = VK_NULL_HANDLE;
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    VkPipeline mPipeline = VK_NULL_HANDLE;
    SubmitStats mStats;
};

} // namespace sb
