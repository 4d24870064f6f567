#pragma once
// `blob` on Vulkan: BlobGL's program (techniques/blob/BlobGL.h says what the technique does) with the
// same declaration, properties, ground, fit and counters (techniques/blob/Blob.h) and the same shaders
// (common/scene.vert + common/lit.frag, common/receiver.*, blob/blob.* and their `#ifdef VULKAN`
// blocks), recorded into the frame's command buffer.
//
// Passes. lighting: the scene lit and unshadowed. blobs: every blob fitted on the CPU (as a game does
// per frame for moving objects) and written into a host-visible storage buffer (grown geometrically; the
// harness waits for each frame's fence, so it is rewritten in place), the ground's rectangle marked in
// the stencil (VulkanReceiverStencil, reference 1) and every blob drawn in one instanced draw of 4-vertex
// strips where it is set (stencil kept: overlapping blobs multiply), colour = dst - src, visibility =
// dst * src. The ground's plane and colour go in the push constants.
#include <optional>
#include <vector>

#include "scenes/ReceiverPlane.h"
#include "techniques/blob/Blob.h"
#include "techniques/vulkan/VulkanReceiverStencil.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"

namespace sb {

class BlobVulkan final : public VulkanTechnique {
public:
    BlobVulkan();
    ~BlobVulkan() override;
    void setScene(const Scene& scene) override;
    /// As on GL: blobs are fitted to the casters and lights in every frame; the ground does not move.
    void sceneChanged(const Scene&, uint32_t) override {}
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }

private:
    void release();
    /// Makes room for `count` records (a new buffer and descriptor write only when it grows).
    void reserve(size_t count);
    void renderBlobs(VulkanFrameContext& ctx);

    VulkanContext* mContext = nullptr;
    VkDevice mDevice = VK_NULL_HANDLE;
    std::optional<ReceiverPlane> mGround;
    std::vector<Aabb> mMeshBounds;    ///< object space, per mesh
    std::vector<Blob::Record> mBlobs; ///< this frame's
    VulkanReceiverStencil mReceiver;
    VulkanBuffer mBlobBuffer; ///< host-visible storage buffer
    size_t mCapacity = 0;     ///< records mBlobBuffer holds
    DescriptorSets mSets;     ///< set 1: the blob records
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    ScenePipeline mLit, mBlob;
    Counters mCounters;
};

} // namespace sb
