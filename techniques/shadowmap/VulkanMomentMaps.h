#pragma once
// The filterable shadow maps of `vsm`, `esm`, `evsm` and `msm` on Vulkan
// (techniques/shadowmap/FilterableShadowMaps.h on GL, whose header describes the method): the same fits,
// culling and counters (MomentMapFits), the same shaders (shadowmap/moments.vert, moments.frag, the
// technique's lighting shader, their `#ifdef VULKAN` blocks) and the same formats: per light a layer of a
// colour array (the member's format, bilinear, clamp to edge) rendered over one depth attachment
// shared by the layers (X8_D24, GL's 24-bit renderbuffer) and blurred by VulkanSeparableBlur.
//
// A light's pass is one render pass that clears its layer to "no occluder" and, where a caster reaches
// its frustum, draws with the receiver background the non-casters (a GREATER pipeline over depth
// cleared to 0: the farthest per texel), clears the depth to 1 and draws the casters (a LESS pipeline:
// the nearest), as GL's glDepthFunc switch. The light's matrix and depth parameters come from one
// dynamic uniform slot per light (LightPass), the lighting pass's uniforms from one block
// (ShadowMapBlock: shadow matrices, depth parameters, the margin and the technique's two parameters),
// all written in compile() and when the scene moves: a frame writes no descriptor.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "techniques/shadowmap/MomentMapFits.h"
#include "techniques/vulkan/ContactShadowsVulkan.h"
#include "techniques/vulkan/LitPipelines.h"
#include "techniques/vulkan/VulkanSeparableBlur.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"
#include "vk/VulkanImage.h"

namespace sb {

class VulkanMomentMaps {
public:
    /// What differs between the members (`vsm`, `esm`, `evsm`, `msm`).
    struct Settings {
        /// R32G32_SFLOAT (vsm, evsm), R32_SFLOAT (esm), R32G32B32A32_SFLOAT (evsm, msm) or
        /// R16G16B16A16_UNORM (msm)
        VkFormat format = VK_FORMAT_UNDEFINED;
        int resolution = 0;
        Defines depthDefines;         ///< moments.frag's (the submitter's, VSM, EVSM_EXPONENTS, MSM)
        std::string lightingFragment; ///< "shadowmap/vsm.frag", "esm.frag", "evsm.frag", "msm.frag"
        Defines lightingDefines;      ///< the lighting pass's (LIGHT_COUNT is added)
        glm::vec2 params{0.0f};       ///< the lighting block's two floats after the margin
        glm::vec4 clear{1.0f};        ///< a layer's "no occluder" value
        VulkanSeparableBlur::Settings blur;
    };

    explicit VulkanMomentMaps(std::string owner) : mOwner(owner), mFits(std::move(owner)) {}
    ~VulkanMomentMaps();
    VulkanMomentMaps(const VulkanMomentMaps&) = delete;
    VulkanMomentMaps& operator=(const VulkanMomentMaps&) = delete;

    /// The light fits; fit() them before compile().
    MomentMapFits& fits() { return mFits; }
    /// Contact shadows (techniques/vulkan/ContactShadowsVulkan.h): compile() it before compile(); the
    /// lighting pipeline takes its set, and renderFrame() its pre-pass (pass "view_depth") and binding.
    ContactShadowsVulkan& contact() { return mContact; }
    const MomentMapFits& fits() const { return mFits; }
    /// A scene in motion moved: the fits follow (MomentMapFits::sceneChanged) and the blocks are
    /// rewritten.
    void sceneChanged(const Scene& scene);
    /// Images, passes, pipelines and blocks for `settings`; returns the permutation key (depth, lighting
    /// and the blur's shaders).
    std::string compile(const VulkanCompileContext& ctx, const Settings& settings);
    /// One frame as FilterableShadowMaps::renderFrame: pass "depth", pass "blur" over the layers a caster
    /// reached, pass "lighting"; returns the counters (MomentMapFits::counters).
    Counters renderFrame(VulkanFrameContext& ctx);

private:
    void release();
    void createImages(VulkanContext& context);
    void createDescriptors(VulkanContext& context);
    void createPipelines(const VulkanCompileContext& ctx);
    void writeBlocks();
    void render(VulkanFrameContext& ctx);
    void renderLayer(VulkanFrameContext& ctx, size_t light, const MomentMapFits::LightDraws& draws);

    std::string mOwner;
    MomentMapFits mFits;
    ContactShadowsVulkan mContact;
    Settings mSettings;
    VkDevice mDevice = VK_NULL_HANDLE;
    int mLayers = 0;
    VkFormat mDepthFormat = VK_FORMAT_UNDEFINED;
    VulkanImage mMaps, mDepth;
    VkRenderPass mPass = VK_NULL_HANDLE;
    std::vector<VkFramebuffer> mFramebuffers; ///< per layer, with the shared depth
    VkSampler mSampler = VK_NULL_HANDLE;
    VulkanBuffer mLightPass; ///< LightPass slots, one per light
    uint32_t mLightStride = 0;
    VulkanBuffer mLightingBlock; ///< ShadowMapBlock of vsm.frag and esm.frag
    static constexpr size_t kDepthSet = 0, kLightingSet = 1;
    DescriptorSets mSets;
    VkPipelineLayout mDepthLayout = VK_NULL_HANDLE, mLightingLayout = VK_NULL_HANDLE;
    VkPipeline mCasterPipeline = VK_NULL_HANDLE, mBackgroundPipeline = VK_NULL_HANDLE;
    LitPipelines mLighting; ///< the lighting pass (non-receivers apart where they can be)
    std::string mKey;
    VulkanSeparableBlur mBlur;
    std::vector<uint8_t> mKeep, mKeepBackground, mHasCasters;
    size_t mCulled = 0;
};

} // namespace sb
