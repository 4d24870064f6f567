#pragma once
// `pcss` on Vulkan: PcssGL's two passes (techniques/shadowmap/PcssGL.h has the method) with the same
// declaration, properties, light fits (FlatLightFits), per-light parameters and Poisson kernels
// (Pcss::lightParams, PoissonDisk), caster culling and shaders (common/depth.vert, common/scene.vert,
// shadowmap/pcss.frag, their `#ifdef VULKAN` blocks), recorded into the frame's command buffer.
//
// Depth pass: ShadowMapVulkan's (techniques/vulkan/VulkanFlatDepthPass.h), one layer per shadowed light of an
// X8_D24 depth array (GL's 24-bit map, so the polygon-offset bias means the same), the light's matrix from a
// dynamic uniform slot. Lighting pass: the uniforms GL sets by location in one block (ShadowMapBlock of
// pcss.frag), and the one map through two samplers as on GL: nearest without comparison for the blocker
// search, linear with a LEQUAL comparison for the filter, both clamped to an opaque white border (depth 1: no
// caster outside the map). Directional and spot lights; a point light is refused as on GL.
#include <vector>

#include <glm/glm.hpp>

#include "scenes/InstanceCulling.h"
#include "techniques/FlatLightFits.h"
#include "techniques/shadowmap/Pcss.h"
#include "techniques/vulkan/ContactShadowsVulkan.h"
#include "techniques/vulkan/LitPipelines.h"
#include "techniques/vulkan/VulkanFlatDepthPass.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"

namespace sb {

class PcssVulkan final : public VulkanTechnique {
public:
    PcssVulkan();
    ~PcssVulkan() override;
    void setScene(const Scene& scene) override;
    void propertiesApplied() override; ///< contact=on's pass "view_depth"
    /// As PcssGL: the light fits, the culling bounds and each light's parameters follow the scene.
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mLights; }

private:
    ContactShadowsVulkan mContact; ///< contact=on: the view depth pre-pass and its set 2
    void release();
    void createDescriptors(VulkanContext& context);
    void fitLightSizes(const Scene& scene); ///< mParams for the current fits and light_size
    void writeBlocks();                     ///< the lighting block and the depth pass's light slots

    VkDevice mDevice = VK_NULL_HANDLE;
    FlatLightFits mLights;
    std::vector<Pcss::LightParams> mParams;
    InstanceCulling mCulling;
    size_t mCulled = 0;
    int mSize = 0, mLayers = 0;
    VulkanFlatDepthPass mDepth;  ///< the maps, a layer and a LightPass slot per light, and their pass
    VulkanBuffer mLightingBlock; ///< pcss.frag's ShadowMapBlock
    DescriptorSets mSets;        ///< the lighting pass's set 1
    VkPipelineLayout mLightingLayout = VK_NULL_HANDLE;
    LitPipelines mLighting; ///< the lighting pass (non-receivers apart where they can be)
    std::vector<glm::vec2> mBlockerKernel, mFilterKernel; ///< unit-disk Poisson taps
    Counters mCounters;
};

} // namespace sb
