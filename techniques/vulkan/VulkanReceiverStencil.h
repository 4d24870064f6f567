#pragma once
// The slides' receiver marking on Vulkan for the planar ad-hoc techniques (`planar`, `blob`), as
// techniques/gl/ReceiverStencil does it on GL: the rectangles of the receiver planes
// (scenes/ReceiverPlane.h) drawn into the stencil where they are visible, so that what is drawn onto a
// receiver afterwards with a stencil test lands on it and nowhere else. The rectangle lies in the
// receiver's own plane; a depth bias pulls it towards the eye so it wins the depth test against the
// receiver it lies on and loses against anything in front of it.
//
// The stencil reference is dynamic in the marking pipeline and in the pipelines darkenState() describes,
// so a pass marks each flattening with a fresh value without building a pipeline per value.
#include <vector>

#include <vulkan/vulkan.h>

#include "scenes/ReceiverPlane.h"
#include "techniques/vulkan/VulkanPipelineCache.h"
#include "vk/GraphicsPipeline.h"
#include "vk/VulkanBuffer.h"

namespace sb {

struct VulkanCompileContext;
struct VulkanFrameContext;

class VulkanReceiverStencil {
public:
    /// The depth bias (glPolygonOffset(factor, units)) of geometry drawn in a receiver's plane, GL's
    /// ReceiverStencil values: factor for the depth slope, units for the rounding of two
    /// triangulations of the same plane.
    static constexpr float kOffsetFactor = -1.0f, kOffsetUnits = -4.0f;

    /// Sets the planes whose rectangles compile() uploads (4 corners each, triangle fans).
    void setPlanes(const std::vector<ReceiverPlane>& planes);
    /// Uploads the rectangles (once per setPlanes) and builds the marking pipeline for `layout` (set 0
    /// the frame block): stencil = reference where the rectangle passes depth LEQUAL, no colour.
    void compile(const VulkanCompileContext& ctx, VkPipelineLayout layout);
    /// Inside an open render pass of the frame targets with the frame block bound: sets the stencil
    /// reference to `ref` and marks receiver `plane`. Leaves the marking pipeline bound.
    void mark(VulkanFrameContext& ctx, size_t plane, uint32_t ref) const;
    /// The state of what darkens a marked receiver (GL's state after ReceiverStencil::mark and
    /// setDarkenBlending): no depth test or writes, stencil EQUAL the dynamic reference with `passOp`
    /// on pass (ZERO: each pixel once; KEEP: any number of times), colour = dst - src, visibility =
    /// dst * src.
    static void darkenState(GraphicsPipelineDesc& d, VkStencilOp passOp);
    /// Two-sided stencil state `compare` with `passOp` on pass, masks 0xff.
    static VkStencilOpState stencilOps(VkCompareOp compare, VkStencilOp passOp);

private:
    std::vector<glm::vec3> mCorners;
    VulkanBuffer mVertices;
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    ScenePipeline mPipeline;
};

} // namespace sb
