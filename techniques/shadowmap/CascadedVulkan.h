#pragma once
// `cascaded` on Vulkan: CascadedGL's two passes with the same declaration, properties, lights, splits,
// fits, shared and empty cascades, caster culling and counters (CascadedMaps, which both forms call)
// and shaders (common/depth.vert, common/scene.vert, shadowmap/cascaded_lighting.frag, their
// `#ifdef VULKAN` blocks), recorded into the frame's command buffer.
//
// Depth pass: one layer per slot of a depth array image (X8_D24 as ShadowMapVulkan's maps, so
// glPolygonOffset's factors mean the same bias); each map CascadedMaps plans is a render pass of its
// own that clears its layer, the slot's view-projection (GL's times VulkanFrameBlock::depthFromGl: z to
// [0, w], no flip) in a dynamic uniform buffer slot (depth.vert's LightPass), depth clamping on as
// GL_DEPTH_CLAMP (casters nearer the light than the box's near side are kept). Slots are rewritten every
// frame: the fits follow the camera. Lighting pass: the uniforms GL sets by location in one block
// (CascadedBlock) and the array through a depth-compare sampler with bilinear filtering.
//
// fit=sdsm (Lauritzen, Salvi and Lefohn 2011, Sample Distribution Shadow Maps, I3D) adds pass
// "depth_range" before "depth", as on GL: the view depth pre-pass (techniques/vulkan/ViewDepthVulkan.h)
// reduced to its min and max by the same compute shader, read back one frame late
// (techniques/shadowmap/DepthRangeVulkan.h), whose interval the splits divide logarithmically.
//
// Device feature: depthClamp; a device without it is refused naming it (ExitCode::Unsupported).
#include <vector>

#include "techniques/shadowmap/CascadedMaps.h"
#include "techniques/shadowmap/DepthRangeVulkan.h"
#include "techniques/vulkan/LitPipelines.h"
#include "techniques/vulkan/ViewDepthVulkan.h"
#include "techniques/vulkan/VulkanDepthMapSet.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"

namespace sb {

class CascadedVulkan final : public VulkanTechnique {
public:
    CascadedVulkan();
    ~CascadedVulkan() override;
    void propertiesApplied() override; ///< fit=sdsm's pass "depth_range"
    void setScene(const Scene& scene) override;
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mPlan; }

    /// As CascadedGL's: the last frame's splits, and fit=sdsm's pre-pass and reduction (for the tests).
    const std::vector<float>& splits() const { return mPlan.splits(); }
    const ViewDepthVulkan& viewDepth() const { return mViewDepth; }
    const DepthRangeVulkan& depthRange() const { return mRange; }

private:
    void release();
    void createDescriptors(VulkanContext& context);
    void createPipelines(const VulkanCompileContext& ctx);
    void renderDepth(VulkanFrameContext& ctx, glm::vec2 samples);
    void drawMap(VulkanFrameContext& ctx, size_t slot);
    void writeLightingBlock();

    VkDevice mDevice = VK_NULL_HANDLE;
    CascadedMaps mPlan;          ///< lights, slots, fits and the depth pass's plan (both APIs')
    std::vector<uint8_t> mKeep;  ///< the depth pass's mask, reused per map
    int mSize = 0, mSlots = 0;   ///< as compiled
    VulkanDepthMapSet mMaps;     ///< a layer and a LightPass slot per slot
    VulkanBuffer mLightingBlock; ///< CascadedBlock
    static constexpr size_t kDepthSet = 0, kLightingSet = 1; ///< in mSets
    DescriptorSets mSets;
    VkPipelineLayout mDepthLayout = VK_NULL_HANDLE, mLightingLayout = VK_NULL_HANDLE;
    VkPipeline mDepthPipeline = VK_NULL_HANDLE;
    LitPipelines mLighting;     ///< the lighting pass (non-receivers apart where they can be)
    ViewDepthVulkan mViewDepth; ///< fit=sdsm and contact=on: the view's depth (their first pass)
    DepthRangeVulkan mRange;    ///< fit=sdsm: its min and max, one frame late
    Counters mCounters;
};

} // namespace sb
