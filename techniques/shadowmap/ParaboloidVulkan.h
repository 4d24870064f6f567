#pragma once
// `paraboloid` on Vulkan: ParaboloidGL's two passes with the same declaration, properties, light
// classification (OmniLightSet), hemisphere culling (OmniCulling, InstanceCulling), caster splitting
// (ParaboloidSplitting) and shaders (common/depth.vert, paraboloid_depth.vert, cube_depth.vert +
// paraboloid_split.geom, common/scene.vert, shadowmap/paraboloid_lighting.frag with omni_lighting.glsl,
// their `#ifdef VULKAN` blocks), recorded into the frame's command buffer.
//
// Maps: one 2D depth array as on GL (layer 2 * light + half for the point lights' halves, then the
// spot and directional lights' flat maps; X8_D24 as ShadowMapVulkan's maps, so glPolygonOffset's
// factors mean the same bias); a scene with no shadowed light gets a 1 x 1 stand-in, so the lighting
// set is always complete (its lookups are compiled out). Depth pass: each layer a render pass of its
// own that clears it (DepthLayers::beginLayer on GL), its data in a slot of a dynamic uniform buffer:
// a flat map's view-projection (depth.vert's LightPass) or a half's ParaboloidPass (light position and
// half, depth range, split angle, rim offset: the uniforms GL sets by location). A half binds the
// splitting pipeline for its wide casters and the per-vertex one for the rest, as GL switches
// programs. The paraboloid's clip z is written in Vulkan's [0, w] by paraboloid_frame.glsl itself (no
// flip: the map is sampled with GL's coordinates). Lighting pass: one uniform block (the shadow
// matrices, map kind and layer, depth range per light) and the array through a depth-compare sampler
// with bilinear filtering.
//
// Device features: shaderClipDistance always (the cut at each half's plane), geometryShader with
// `split` = true (the default); a device without one is refused naming it (ExitCode::Unsupported).
#include <vector>

#include <glm/glm.hpp>

#include "scenes/InstanceCulling.h"
#include "techniques/shadowmap/OmniCulling.h"
#include "techniques/shadowmap/OmniLightSet.h"
#include "techniques/shadowmap/ParaboloidSplitting.h"
#include "techniques/vulkan/ContactShadowsVulkan.h"
#include "techniques/vulkan/LitPipelines.h"
#include "techniques/vulkan/VulkanDepthMapSet.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"

namespace sb {

class ParaboloidVulkan final : public VulkanTechnique {
public:
    ParaboloidVulkan();
    ~ParaboloidVulkan() override;
    void setScene(const Scene& scene) override;
    void propertiesApplied() override; ///< contact=on's pass "view_depth"
    /// As the GL form (the whole setScene: lights refitted, casters' bounds and edges), then the slots
    /// and the lighting block rewritten: a scene in motion moved the fits.
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mLights; }

private:
    ContactShadowsVulkan mContact; ///< contact=on: the view depth pre-pass and its set 2
    void release();
    void checkFeatures(const VulkanContext& context) const;
    void createDescriptors(VulkanContext& context);
    void createDepthPipelines(const VulkanCompileContext& ctx);
    void writeBlocks();
    void bindSlot(VulkanFrameContext& ctx, uint32_t slot);
    void renderDepth(VulkanFrameContext& ctx);
    void renderFlatMaps(VulkanFrameContext& ctx);
    void renderHemispheres(VulkanFrameContext& ctx);
    /// Draws mKeep's casters into the open half, as ParaboloidGL::drawHemisphere: the wide ones through
    /// the splitting pipeline, the rest per vertex.
    void drawHemisphere(VulkanFrameContext& ctx, const glm::vec3& light, uint32_t slot);
    int flatBase() const { return 2 * mOmniCount; } ///< first layer of the flat maps
    /// Slots of the depth pass's uniform buffer: flat maps, then halves.
    uint32_t flatSlot(int index) const { return uint32_t(index); }
    uint32_t halfSlot(int light, int half) const { return uint32_t(mFlatCount + 2 * light + half); }

    VkDevice mDevice = VK_NULL_HANDLE;
    OmniLightSet mLights;
    InstanceCulling mCulling;
    OmniCulling mOmniCulling;
    ParaboloidSplitting mSplitting;
    std::vector<uint8_t> mKeep, mKeepPlain, mKeepSplit;
    bool mSplit = true; ///< property split: route wide casters through the splitting pipeline
    float mMaxSegmentAngle = 0.0f, mBeyondRim = 0.0f;
    int mSize = 0, mOmniCount = 0, mFlatCount = 0, mLayers = 0; ///< as compiled (mLayers 0: no map)
    size_t mCulled = 0, mSplitDrawn = 0;
    int mHemispheresRendered = 0;

    VulkanDepthMapSet mMaps;     ///< the layers, and LightPass or ParaboloidPass slots
    VulkanBuffer mLightingBlock; ///< omni_lighting.glsl's block
    static constexpr size_t kDepthSet = 0, kLightingSet = 1; ///< in mSets
    DescriptorSets mSets;
    VkPipelineLayout mDepthLayout = VK_NULL_HANDLE, mLightingLayout = VK_NULL_HANDLE;
    VkPipeline mFlatDepth = VK_NULL_HANDLE, mParaboloidDepth = VK_NULL_HANDLE, mSplitDepth = VK_NULL_HANDLE;
    LitPipelines mLighting; ///< the lighting pass (non-receivers apart where they can be)
    Counters mCounters;
};

} // namespace sb
