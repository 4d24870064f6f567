#pragma once
// `planar` on Vulkan: PlanarGL's program (techniques/planar/PlanarGL.h says what the technique does) with
// the same declaration, properties, flattenings, proxy records and counters (techniques/planar/Planar.h)
// and the same shaders (common/scene.vert + common/lit.frag, planar/shadow.*, common/receiver.* and
// their `#ifdef VULKAN` blocks), recorded into the frame's command buffer.
//
// Passes. lighting: the scene lit and unshadowed. shadows: one render pass; per flattening (a receiver
// plane and a light in front of it) with stencil=true the receiver's rectangle marks the stencil with a
// fresh dynamic reference (VulkanReceiverStencil, as GL's glStencilFunc values; after 255 flattenings
// a stencil clear) and the flattened occluders are drawn without depth test where it is set, zeroing
// it; with stencil=false they are depth-tested LEQUAL against the receiver with GL's polygon offset as
// a depth bias. Colour = dst - src, visibility = dst * src, as GL's blending.
//
// Per-flattening data (the flattening matrix, plane, homogeneous light, receiver albedo with the
// light's index, darkness) lives in one host-visible uniform buffer, a record per flattening (room for
// every plane and light) bound at a dynamic offset: written when the flattenings change (compile, lights
// moved), never per frame. occluder=proxy draws the unit shapes (Planar::unitShapes) instanced from the
// technique's own instance buffer, rewritten in place when casters move. guards=true needs the
// shaderClipDistance feature (ExitCode::Unsupported without it).
#include <vector>

#include "scenes/InstanceCulling.h"
#include "scenes/ReceiverPlane.h"
#include "techniques/planar/Planar.h"
#include "techniques/vulkan/VulkanReceiverStencil.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"

namespace sb {

class PlanarVulkan final : public VulkanTechnique {
public:
    PlanarVulkan();
    ~PlanarVulkan() override;
    void setScene(const Scene& scene) override;
    /// As on GL: the flattenings follow the lights; the proxy occluders (occluder=proxy) the casters.
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }

private:
    struct ShapeGpu {
        VulkanBuffer vertices, indices;
        uint32_t indexCount = 0;
    };
    void release();
    void readProperties();
    void uploadProxyShapes(VulkanContext& context);
    void writeProxyRecords(VulkanContext& context);
    void writeFlattenings();
    void buildPipelines(const VulkanCompileContext& ctx);
    /// The "shadows" pass: every flattening of a caster onto a receiver plane, per light.
    void renderShadows(VulkanFrameContext& ctx);
    void drawOccluders(VulkanFrameContext& ctx, size_t index, InstanceMask keep);

    const Scene* mScene = nullptr;
    VulkanContext* mContext = nullptr;
    VkDevice mDevice = VK_NULL_HANDLE;
    std::vector<ReceiverPlane> mPlanes;
    std::vector<Planar::Projection> mProjections;
    VulkanReceiverStencil mReceivers;
    Planar::ProxyPlan mProxies;
    std::vector<ShapeGpu> mShapes; ///< Planar::unitShapes() in buffers
    VulkanBuffer mProxyInstances;  ///< host-visible: mProxies.records
    bool mProxiesDirty = true;
    bool mStencil = true, mUseProxies = false, mGuards = true, mCull = true;
    float mDarkness = 1.0f;
    InstanceCulling mCulling;   ///< the casters' bounds, for cull
    std::vector<uint8_t> mKeep; ///< the casters one flattening keeps
    size_t mCulled = 0;         ///< casters left out over the frame's flattenings

    VulkanBuffer mFlattenings; ///< host-visible: one record per flattening, mStride apart
    uint32_t mStride = 0;
    DescriptorSets mSets;                      ///< set 1: the flattening record (dynamic)
    VkPipelineLayout mLayout = VK_NULL_HANDLE; ///< frame block, flattening, push constants
    ScenePipeline mLit, mShadow, mProxy;
    Counters mCounters;
};

} // namespace sb
