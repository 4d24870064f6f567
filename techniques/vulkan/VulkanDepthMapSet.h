#pragma once
// The depth maps one Vulkan form of the shadow-map family renders and samples, and what goes with them
// (ShadowMapVulkan, PcssVulkan, CascadedVulkan, ParaboloidVulkan; CubeMapVulkan holds two, its cubes
// and its flat maps; a technique outside the family that needs a light's depth map): the image of
// layers (VulkanDepthMaps::image), the render pass a layer is drawn with, a framebuffer per drawn layer
// (or one over all of them for a layered pass), the samplers the lighting pass reads it through, and the
// depth pass's dynamic uniform slots (UniformSlots). Everything is released with the set.
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/GraphicsPipeline.h"
#include "vk/LayerPasses.h"
#include "vk/UniformSlots.h"
#include "vk/VulkanImage.h"

namespace sb {

class PropertySet;
class VulkanContext;

class VulkanDepthMapSet {
public:
    VulkanDepthMapSet() = default;
    /// `layers` layers of size^2 (a cube array when `cube`) cleared to the far plane, the depth render
    /// pass (VulkanDepthMaps::renderPass) and a framebuffer of one layer for each of the first `drawn`
    /// layers (fewer than `layers` where a stand-in layer is never drawn).
    VulkanDepthMapSet(VulkanContext& context, uint32_t size, uint32_t layers, uint32_t drawn,
                      bool cube = false);
    ~VulkanDepthMapSet();
    VulkanDepthMapSet(VulkanDepthMapSet&& other) noexcept;
    VulkanDepthMapSet& operator=(VulkanDepthMapSet&& other) noexcept;
    VulkanDepthMapSet(const VulkanDepthMapSet&) = delete;
    VulkanDepthMapSet& operator=(const VulkanDepthMapSet&) = delete;

    /// One more framebuffer, over every layer through a 2D-array view of them all: the target of a
    /// layered pass whose geometry stage routes each triangle with gl_Layer. Returns its index.
    size_t addLayeredFramebuffer();
    /// A sampler of the maps, owned by the set (VulkanDepthMaps::sampler's, or one of its own).
    VkSampler addSampler(const LayerPasses::Sampling& sampling, const char* what);
    /// VulkanDepthMaps::sampler(compare), owned by the set.
    VkSampler addSampler(bool compare);
    /// The depth pass's slots: `count` of `bytes` each (a light's matrix, a pass's block), zeroed.
    void createSlots(VulkanContext& context, VkDeviceSize bytes, uint32_t count);

    const UniformSlots& slots() const { return mSlots; }
    VkImageView view() const { return mImage.view(); } ///< every layer, as the lighting pass samples them
    VkRenderPass pass() const { return mPass; }
    uint32_t size() const { return mSize; }
    uint32_t layers() const { return mLayers; }
    /// The fragment stage of every depth pass into these maps: none. The pipeline writes depth only, so it
    /// needs no fragment shader (legal in Vulkan: the depth test, the write and the bias still apply), and
    /// a GPU driver then has no fragment work to launch. lavapipe binds an empty shader of its own in that
    /// case, so on it the work and the pipeline statistics are those of the GL forms' empty
    /// shaders/common/depth.frag (which says why GL gains nothing from leaving it out either).
    static constexpr const char* kDepthFragment = "";
    /// Makes `desc` a depth pass into these maps: no colour, the set's render pass, and the depth bias
    /// of glPolygonOffset(biasSlope, biasConstant).
    void depthPipeline(GraphicsPipelineDesc& desc, double biasSlope, double biasConstant) const;
    /// The same with bias_slope and bias_constant from `properties` (ShadowMapProperties).
    void depthPipeline(GraphicsPipelineDesc& desc, const PropertySet& properties) const;
    /// The pipeline-cache key of that bias, "|bias=slope,constant|", appended to the pass's name.
    static std::string biasKey(double biasSlope, double biasConstant);
    static std::string biasKey(const PropertySet& properties);
    /// Begins the render pass over framebuffer `index`, which clears its layers to the far plane, with
    /// the viewport and scissor of the whole map.
    void begin(VkCommandBuffer cmd, size_t index) const;

private:
    void release();

    VkDevice mDevice = VK_NULL_HANDLE;
    uint32_t mSize = 0, mLayers = 0;
    VkFormat mFormat = VK_FORMAT_UNDEFINED;
    VulkanImage mImage;
    VkRenderPass mPass = VK_NULL_HANDLE;
    std::vector<VkFramebuffer> mFramebuffers;
    VkImageView mLayersView = VK_NULL_HANDLE; ///< addLayeredFramebuffer's view
    std::vector<VkSampler> mSamplers;
    UniformSlots mSlots;
};

} // namespace sb
