#pragma once
// `shadowmap` on Vulkan: ShadowMapGL's two passes with the same declaration, properties, light
// fits (FlatLightFits), caster culling and shaders (common/depth.vert, common/scene.vert,
// shadowmap/lighting.frag, their `#ifdef VULKAN` blocks), recorded into the frame's command buffer.
//
// Depth pass: one layer per shadowed light of a depth array image (X8_D24, the GL map's 24-bit depth,
// so the same polygon-offset factors mean the same bias), each a render pass of its own that clears it,
// the light's view-projection from a dynamic uniform buffer slot (LightPass), slope and constant depth
// bias as glPolygonOffset(slope, constant) (techniques/vulkan/VulkanFlatDepthPass.h). Lighting pass: the map
// through a depth-compare sampler (hardware_compare) or a nearest one, and the uniforms GL sets by location
// in one block (ShadowMapBlock). Directional and spot lights; a point light is refused as on GL.
#include <vector>

#include <glm/glm.hpp>

#include "scenes/InstanceCulling.h"
#include "techniques/FlatLightFits.h"
#include "techniques/vulkan/ContactShadowsVulkan.h"
#include "techniques/vulkan/LitPipelines.h"
#include "techniques/vulkan/VulkanFlatDepthPass.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"

namespace sb {

class ShadowMapVulkan final : public VulkanTechnique {
public:
    ShadowMapVulkan();
    ~ShadowMapVulkan() override;
    void propertiesApplied() override; ///< contact=on's pass "view_depth"
    void setScene(const Scene& scene) override;
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mLights; }

private:
    void release();
    void createDescriptors(VulkanContext& context);
    void fitTexels(const Scene& scene);
    void writeLightingBlock(float targetHeight);
    void renderDepth(VulkanFrameContext& ctx);
    /// The lit pass (LitPipelines::draw: the non-receivers apart where they can be).
    void renderLighting(VulkanFrameContext& ctx);

    VkDevice mDevice = VK_NULL_HANDLE;
    FlatLightFits mLights;
    InstanceCulling mCulling;
    size_t mCulled = 0;
    int mSize = 0, mLayers = 0;
    VulkanFlatDepthPass mDepth;  ///< the maps, a layer and a LightPass slot per light, and their pass
    VulkanBuffer mLightingBlock; ///< ShadowMapBlock
    DescriptorSets mSets;        ///< the lighting pass's set 1
    VkPipelineLayout mLightingLayout = VK_NULL_HANDLE;
    LitPipelines mLighting;
    ContactShadowsVulkan mContact; ///< contact=on: the view depth pre-pass and its set 2

    std::vector<glm::vec2> mKernel;
    std::vector<float> mTexelWorld;
    float mNormalOffset = 0.0f;
    bool mCull = true;
    ViewCull mView;
    Counters mCounters;
};

} // namespace sb
