#pragma once
// The depth pass of the flat maps on Vulkan: one layer per light of a FlatLightFits (techniques/
// FlatLightFits.h), drawn with common/depth.vert. It owns the maps (a VulkanDepthMapSet with a LightPass
// slot per light), the pass's set 1 (the light's matrix, one dynamic slot per light), its pipeline layout
// and pipeline (casters only, no colour, no fragment stage, the depth bias of glPolygonOffset(slope,
// constant)), and records one frame's layers, each light's casters culled to its frustum and, given a
// ViewCull, to those whose shadow can reach the view. `shadowmap` and `pcss` render their maps with it,
// and so does any technique outside the family that needs a light's depth map: one recording, not one
// per technique. What the lighting pass reads (its samplers over maps().view(), its own set) stays the
// technique's.
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "scenes/InstanceCulling.h"
#include "techniques/FlatLightFits.h"
#include "techniques/vulkan/VulkanDepthMapSet.h"
#include "vk/DescriptorSets.h"

namespace sb {

struct VulkanCompileContext;
struct VulkanFrameContext;

class VulkanFlatDepthPass {
public:
    VulkanFlatDepthPass() = default;
    /// `layers` maps of size^2 (one per light, at least one) and the pass's pipeline, named
    /// "<name>-depth|bias=<slope>,<constant>|" in the pipeline cache (VulkanDepthMapSet::biasKey).
    VulkanFlatDepthPass(const VulkanCompileContext& ctx, const std::string& name, uint32_t size,
                        uint32_t layers, double biasSlope, double biasConstant);
    ~VulkanFlatDepthPass();
    VulkanFlatDepthPass(VulkanFlatDepthPass&& other) noexcept;
    VulkanFlatDepthPass& operator=(VulkanFlatDepthPass&& other) noexcept;
    VulkanFlatDepthPass(const VulkanFlatDepthPass&) = delete;
    VulkanFlatDepthPass& operator=(const VulkanFlatDepthPass&) = delete;

    /// The maps: the lighting pass's samplers (addSampler) and view() come from here.
    VulkanDepthMapSet& maps() { return mMaps; }
    const VulkanDepthMapSet& maps() const { return mMaps; }
    /// Each light's matrix into its slot, in Vulkan's depth range without a flip
    /// (VulkanFrameBlock::depthFromGl): after every fit (compile, a scene in motion).
    void writeLights(const FlatLightFits& lights) const;
    /// Records the layer of every light with a map (FlatLightFits::castsShadow), outside a render pass:
    /// each clears its layer and draws the casters `culling` keeps in the light's frustum (and, with
    /// `view`, that reach the view). Returns how many casters were culled over all lights.
    size_t record(VulkanFrameContext& ctx, const FlatLightFits& lights, const InstanceCulling& culling,
                  const ViewCull* view = nullptr);

private:
    void release();

    VkDevice mDevice = VK_NULL_HANDLE;
    VulkanDepthMapSet mMaps;
    DescriptorSets mSet; ///< set 1 of common/depth.vert: LightPass
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    VkPipeline mPipeline = VK_NULL_HANDLE; ///< owned by the pipeline cache
    std::vector<uint8_t> mKeep;            ///< the casters one light's pass draws
};

} // namespace sb
