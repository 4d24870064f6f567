#pragma once
// The depth range of the camera's view on Vulkan, what `cascaded` fit=sdsm splits: DepthRangeGL's
// reduction (techniques/shadowmap/DepthRangeGL.h says what and why) of the view depth pre-pass
// (techniques/vulkan/ViewDepthVulkan.h) with the same compute shader (shaders/shadowmap/depth_range.comp,
// its `#ifdef VULKAN` bindings: set 0, the depth image through a NEAREST sampler at binding 0, the answer
// buffer at binding 1), into one of two host-visible buffers alternately.
//
// The same one frame of latency as on GL: the harness waits for every frame's fence before recording the
// next, so frame k reads frame k-1's buffer through its mapping while recording, without a stall. The
// first frame after a scene change has no earlier answer: it records its pre-pass and reduction into a
// command buffer of its own, submitted and waited for at once (VulkanContext::submitNow), and fits to
// that; its frame's command buffer then holds no second pre-pass (the image already holds this frame's
// view depth), so its draw counts are GL's, and pass "depth_range"'s GPU time on that one frame is
// empty.
#include <array>
#include <cstdint>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "techniques/vulkan/ViewDepthVulkan.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"

namespace sb {

class VulkanContext;
struct VulkanCompileContext;
struct VulkanFrameContext;

class DepthRangeVulkan {
public:
    DepthRangeVulkan() = default;
    ~DepthRangeVulkan();
    DepthRangeVulkan(const DepthRangeVulkan&) = delete;
    DepthRangeVulkan& operator=(const DepthRangeVulkan&) = delete;

    /// The reduction's pipeline, its two answer buffers and their sets over `depth`'s image (compiled
    /// before this: its image is what the sets point at).
    void compile(const VulkanCompileContext& ctx, const ViewDepthVulkan& depth);
    /// Forgets the answers of earlier frames (a new scene): the next frame reads its own.
    void reset() { mFrames = 0; }
    /// Records `depth`'s pre-pass and this frame's reduction of it (into ctx.cmd, or on the first frame
    /// submitted at once); returns the view-depth interval (x near, y far; x > y when no texel is
    /// covered) to fit this frame's cascades to: the last frame's, or this one's on the first frame.
    glm::vec2 run(const VulkanFrameContext& ctx, ViewDepthVulkan& depth);

    /// The window depths (x min, y max) of the answer run() returned last (x > y: none covered).
    glm::vec2 windowRange() const { return mWindow; }
    /// The window depths in the buffer of the last frame's reduction, once that frame has finished: what
    /// the tests compare with the image read back.
    glm::vec2 latestWindowRange() const;

private:
    void release();
    void record(VkCommandBuffer cmd, const ViewDepthVulkan& depth, size_t buffer);
    glm::vec2 readWindow(size_t buffer) const;

    VulkanContext* mContext = nullptr;
    VkDevice mDevice = VK_NULL_HANDLE;
    VkSampler mSampler = VK_NULL_HANDLE;
    std::array<VulkanBuffer, 2> mBuffers; ///< the answer, frame by frame alternately (host-visible)
    DescriptorSets mSets;                 ///< set i: the depth image and mBuffers[i]
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    VkPipeline mPipeline = VK_NULL_HANDLE;
    std::array<glm::mat4, 2> mProj{}; ///< the projection that buffer's depths were rendered with
    uint64_t mFrames = 0;             ///< frames run since the last reset
    glm::vec2 mWindow{1.0f, 0.0f};
};

} // namespace sb
