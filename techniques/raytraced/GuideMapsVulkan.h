#pragma once
// What `raytraced:mode=guided` adds to the Vulkan form (techniques/raytraced/GuidedRays.h has the rule):
// a depth map per light that can have one, rendered in the pass "depth" with the shadow-map family's
// pieces (techniques/FlatLightFits.h for the cameras, techniques/vulkan/VulkanFlatDepthPass.h for the
// maps and their pass, with no depth bias), and the lighting pass's set 2 of shaders/raytraced/guided.glsl:
//   binding 0  GuidedBlock: per light the map's matrix, texel size, whether it has a map and is
//              directional; the margin and the depth steps
//   binding 1  the maps, nearest, read by texelFetch
//   binding 2  the count of pixel-lights the maps decided (a host-visible uint, zeroed each frame)
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "scenes/InstanceCulling.h"
#include "techniques/FlatLightFits.h"
#include "techniques/PropertySet.h"
#include "techniques/vulkan/VulkanFlatDepthPass.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"

namespace sb {

struct VulkanCompileContext;
struct VulkanFrameContext;

class GuideMapsVulkan {
public:
    /// Fits the maps' cameras (untimed), point lights left without a map.
    void setScene(const Scene& scene, const PropertySet& p);
    /// A scene in motion: the cameras follow the lights and casters (inside the timed frame).
    void sceneChanged(const Scene& scene, const PropertySet& p);
    /// The maps, their pass, the block and the counter for `p`; afterwards layout() is set 2's layout.
    void compile(const VulkanCompileContext& ctx, const PropertySet& p);
    VkDescriptorSetLayout layout() const { return mSets.layout(0); }

    /// Records the maps (inside the caller's pass "depth").
    void recordDepth(VulkanFrameContext& ctx);
    /// Zeroes the count of decisions, before the frame's lighting pass is submitted.
    void resetCount() const;
    /// Binds set 2 for the lighting pass's `layout` (before the pass binds sets 0 and 1 with it).
    void bind(VkCommandBuffer cmd, VkPipelineLayout layout) const;
    /// Pixel-lights the maps decided in the last frame (read after its fence).
    uint64_t decided() const;
    /// Texels of the maps that are drawn (lights with a map x resolution^2).
    double mapTexels() const;

private:
    void writeBlock() const;

    FlatLightFits mLights;
    std::vector<uint8_t> mDirectional; ///< per light: an orthographic map (off the map: no caster)
    InstanceCulling mCulling;
    float mMargin = 0.0f;
    int mSize = 0;
    VulkanFlatDepthPass mDepth;
    VulkanBuffer mBlock;   ///< GuidedBlock
    VulkanBuffer mDecided; ///< GuidedCount: one uint
    DescriptorSets mSets;
};

} // namespace sb
