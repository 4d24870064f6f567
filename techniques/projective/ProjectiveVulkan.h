#pragma once
// `projective` on Vulkan: ProjectiveGL's program (techniques/projective/ProjectiveGL.h says what the
// technique does) with the same declaration, properties, projectors and counters
// (techniques/projective/Projective.h) and the same shaders (projective/texture.*, common/scene.vert with
// SHADOW_MAP + projective/lighting.frag, common/scene.vert + common/lit.frag, and their `#ifdef VULKAN`
// blocks), recorded into the frame's command buffer.
//
// Passes. texture: per light that casts shadows, one render pass into its layer of an R8 2D array
// (cleared to white, no depth attachment: a silhouette), the casters black, each light's projector at
// its dynamic offset of one uniform buffer (Vulkan's depth range, no flip:
// VulkanFrameBlock::depthFromGl). blur: skipped at blur 0 ("blur 0"); otherwise GL's point-sampled
// Gaussian of radius `blur` with a lit (1) outside, per layer that casts (VulkanSeparableBlur, the same
// shader and permutation as ProjectiveGL's SeparableBlur), two render passes per layer. lighting: the casters
// lit and unshadowed, then the non-casters with the textures projected (set 1: the texture matrices and the
// array through a bilinear sampler whose border is white: lit outside the frustum).
//
// Nothing is written per frame: the projectors are fitted in setScene, as on GL, and refitted with the
// scene in motion (sceneChanged rewrites the matrices the frames read).
#include <vector>

#include "scenes/InstanceCulling.h"
#include "techniques/projective/Projective.h"
#include "techniques/vulkan/VulkanSeparableBlur.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"
#include "vk/VulkanImage.h"

namespace sb {

class ProjectiveVulkan final : public VulkanTechnique {
public:
    ProjectiveVulkan();
    ~ProjectiveVulkan() override;
    void setScene(const Scene& scene) override;
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }

private:
    void release();
    void createTextures(VulkanContext& context, uint32_t layers);
    void createDescriptors(VulkanContext& context, uint32_t layers);
    void writeMatrices(); ///< the projectors' and texture matrices of mPlan into their buffers
    void buildPipelines(const VulkanCompileContext& ctx);
    void renderTexture(VulkanFrameContext& ctx);
    int renderBlur(VulkanFrameContext& ctx); ///< returns the number of blur passes (as GL's counter)
    void renderLighting(VulkanFrameContext& ctx);

    VkDevice mDevice = VK_NULL_HANDLE;
    Projective::Plan mPlan;
    int mResolution = 0, mBlurRadius = 0;
    bool mCull = true;
    InstanceCulling mCulling;   ///< the casters' bounds
    std::vector<uint8_t> mKeep; ///< the casters a light's texture keeps
    size_t mCulled = 0;         ///< casters left out over the frame's textures

    VulkanImage mArray;        ///< R8 2D array, one layer per light
    VulkanSeparableBlur mBlur; ///< the layers' blur (its intermediate: R8 2D)
    VkRenderPass mTexturePass = VK_NULL_HANDLE;
    std::vector<VkFramebuffer> mFramebuffers; ///< per layer
    VkSampler mSampler = VK_NULL_HANDLE;
    VulkanBuffer mProjectors; ///< per layer at mStride: Vulkan's projector (texture pass)
    VulkanBuffer mMatrices;   ///< the texture matrices (lighting pass)
    uint32_t mStride = 0;
    DescriptorSets mSets; ///< set 1 of the texture pass, set 1 of the lighting pass
    VkPipelineLayout mTextureLayout = VK_NULL_HANDLE, mLightingLayout = VK_NULL_HANDLE;
    VkPipeline mTexturePipeline = VK_NULL_HANDLE;
    ScenePipeline mLit, mProjective;
    Counters mCounters;
};

} // namespace sb
