#pragma once
// `occluder` on Vulkan: OccluderGL's one lighting pass with the same declaration, properties, planes,
// textures, records and shaders (shaders/occluder/scene.vert and lit.frag; their `#ifdef VULKAN` block
// puts GL's bindings into set 1), recorded into the frame's command buffer. What both forms share is
// OccluderPlan (techniques/occluder/OccluderPlan.h).
//
// compile(): the occluder textures baked with Vulkan (OccluderBakeVulkan: the same bake shaders and
// steps, memoised per mesh and device as GL's bakes are per renderer) or loaded from their files, one
// R8 array image sampled bilinearly and clamped as on GL; the plane records, receiver sections,
// instance records, texture matrices and receivers=all's world planes and candidates in host-visible
// storage buffers, each bound once in one descriptor set. A frame writes in place only what changes per
// frame (per_instance's light space, texture_matrix's matrices) and draws the scene once.
#include "techniques/occluder/OccluderPlan.h"
#include "techniques/vulkan/ScenePass.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"
#include "vk/VulkanImage.h"

namespace sb {

class OccluderVulkan final : public VulkanTechnique {
public:
    OccluderVulkan();
    ~OccluderVulkan() override;
    void setScene(const Scene& scene) override;
    /// As OccluderGL's: the inverse transforms, and with receivers=all the world planes and candidates.
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }

private:
    void release();
    void buildTextures(const VulkanCompileContext& ctx);
    void createBuffers(VulkanContext& context);
    /// receivers=all: the world planes and candidates written (buffers grown, descriptors rewritten,
    /// only when they no longer fit: sceneChanged between frames).
    void writeWorldPlanes();
    /// Host-visible storage buffer of at least `bytes` (and 16) bytes holding `data`.
    VulkanBuffer storage(VulkanContext& context, const void* data, size_t bytes) const;

    OccluderPlan mPlan;
    VulkanContext* mContext = nullptr;
    VkDevice mDevice = VK_NULL_HANDLE;
    VulkanImage mTextures;
    VkSampler mSampler = VK_NULL_HANDLE;
    VulkanBuffer mPlaneBuffer, mInstanceBuffer, mMatrixBuffer, mSectionBuffer, mWorldPlaneBuffer,
        mCandidateBuffer;
    DescriptorSets mSets;
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    ScenePipeline mPipeline;
    int mResolution = 0, mLayers = 0;
    Counters mCounters;
};

} // namespace sb
