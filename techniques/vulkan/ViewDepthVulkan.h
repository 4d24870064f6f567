#pragma once
// The depth pre-pass of the camera's view on Vulkan (techniques/ViewDepth.h says what it draws and why it
// exists; techniques/gl/ViewDepthGL.h is the GL form): a VK_FORMAT_D32_SFLOAT image of the frame's size,
// its render pass (cleared to 1, stored, left DEPTH_STENCIL_READ_ONLY for the compute and fragment
// stages that read it) and framebuffer, and a pipeline drawing every instance with common/depth.vert
// (its LightPass block holding the camera's view-projection in the frame block's clip space,
// VulkanFrameBlock::clipFromGl: y flipped, so its rows are the frame targets' rows). A technique owns
// one and records it where its first reader needs it: `cascaded` fit=sdsm's depth-range reduction
// (techniques/shadowmap/DepthRangeVulkan.h) reads it, and so may a lighting pass (contact shadows).
#include <cstdint>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"
#include "vk/VulkanImage.h"

namespace sb {

struct VulkanCompileContext;
struct VulkanFrameContext;

class ViewDepthVulkan {
public:
    ViewDepthVulkan() = default;
    ~ViewDepthVulkan();
    ViewDepthVulkan(const ViewDepthVulkan&) = delete;
    ViewDepthVulkan& operator=(const ViewDepthVulkan&) = delete;

    /// The image at the targets' size, its pass and the pipeline (the submitter's defines; the device
    /// must attach and sample D32_SFLOAT, else ExitCode::Unsupported naming the device).
    void compile(const VulkanCompileContext& ctx);
    /// Records this frame's view depth into `cmd` (ctx.cmd, or a command buffer of its own that the
    /// caller submits at once: the frame block slot and the matrix written here stay valid until the
    /// frame ends), outside a render pass; the image is then readable by compute and fragment shaders.
    void record(const VulkanFrameContext& ctx, VkCommandBuffer cmd);

    /// The set a lighting pass reads it through (shaders/common/contact_shadow.glsl: set kLightingSet,
    /// uViewDepth at binding 0 through a NEAREST sampler, its 16-byte ContactBlock at binding 1): its
    /// layout goes into the pipeline layout at that index, and bindForLighting writes `block`
    /// (ContactShadows::block; the previous frame's fence was waited for) and binds the set there before
    /// the pass (outside the render pass; binding the lower sets of the same layout after it leaves it
    /// bound).
    static constexpr uint32_t kLightingSet = 2;
    VkDescriptorSetLayout lightingSetLayout() const { return mLightingSet.layout(0); }
    void bindForLighting(VkCommandBuffer cmd, VkPipelineLayout layout, const glm::vec4& block) const;

    VkImage image() const { return mImage.image(); }
    VkImageView view() const { return mImage.view(); } ///< sampled in DEPTH_STENCIL_READ_ONLY_OPTIMAL
    uint32_t width() const { return mWidth; }
    uint32_t height() const { return mHeight; }
    /// The camera projection (GL's) of the last record: what its window depths are view depths under
    /// (ViewDepth::viewDepths; Vulkan's window depth equals GL's through clipFromGl's z).
    const glm::mat4& proj() const { return mProj; }

private:
    void release();

    VkDevice mDevice = VK_NULL_HANDLE;
    uint32_t mWidth = 0, mHeight = 0;
    VulkanImage mImage;
    VkRenderPass mPass = VK_NULL_HANDLE;
    VkFramebuffer mFramebuffer = VK_NULL_HANDLE;
    VulkanBuffer mMatrix; ///< LightPass: the camera's view-projection (host-visible)
    DescriptorSets mSet;  ///< set 1 of common/depth.vert
    VkSampler mSampler = VK_NULL_HANDLE;
    DescriptorSets mLightingSet; ///< a lighting pass's view of the image and its block
    VulkanBuffer mLightingBlock; ///< ContactBlock (host-visible)
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    VkPipeline mPipeline = VK_NULL_HANDLE; ///< owned by the pipeline cache
    glm::mat4 mProj{1.0f};
};

} // namespace sb
