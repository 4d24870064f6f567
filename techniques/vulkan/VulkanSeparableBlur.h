#pragma once
// The separable Gaussian blur of the filterable shadow maps on Vulkan (techniques/gl/SeparableBlur.h on
// GL, whose header describes the kernel and the modes): per layer of a 2D array image, a horizontal pass
// from the layer into one intermediate 2D image, then a vertical pass from it back into the layer
// (shaders/common/blur.frag, its `#ifdef VULKAN` block), each a render pass of one full-screen triangle.
// Both of GL's kernels: the texel-integral one (`vsm`, `esm`; linear or log space), whose weights are
// GaussianKernel's, the same floats as GL's, and the point-sampled one (`projective`: Settings::
// pointSampled, the weights computed in the shader as on GL, the first channel only); taps outside the
// layer read the edge texel, or 1 (Settings::outsideOne, GL's Border::One). The weights and the exponent
// are written once in compile() (a uniform block), the layer is a push constant: a frame records no
// descriptor write.
//
// What the layers must be before apply(): written by a render pass whose end makes its colour writes
// visible to fragment-shader reads and leaves the image SHADER_READ_ONLY_OPTIMAL; apply() leaves them
// so too.
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"
#include "vk/VulkanImage.h"

namespace sb {

class ShaderModuleCache;
class VulkanContext;
class VulkanPipelineCache;

class VulkanSeparableBlur {
public:
    /// One blur's permutation and target.
    struct Settings {
        int width = 0;         ///< the kernel's width in texels (0 and 1: no blur)
        bool logSpace = false; ///< filter exp(c d) of the first channel (ESM) instead of each linearly
        float exponent = 1.0f; ///< c of the log-space mode
        int resolution = 0;    ///< the layers' width and height
        VkFormat format = VK_FORMAT_UNDEFINED; ///< the layers' format, the intermediate's too
        bool pointSampled = false; ///< GL's Kernel::PointSampled: `width` is the radius (taps |k| <= width)
        bool outsideOne = false;   ///< GL's Border::One: taps outside the layer read 1, not the edge texel
    };

    VulkanSeparableBlur() = default;
    ~VulkanSeparableBlur();
    VulkanSeparableBlur(const VulkanSeparableBlur&) = delete;
    VulkanSeparableBlur& operator=(const VulkanSeparableBlur&) = delete;

    /// The intermediate image, render pass, framebuffers and pipelines for `settings`, blurring `array`
    /// (its whole-array view is sampled, its layer views are written). Returns the shaders' permutation
    /// key (horizontal|vertical; "" for a one-tap kernel, which makes nothing). Throws
    /// std::invalid_argument for the log-space mode with the point-sampled kernel (not built, as on GL).
    std::string compile(VulkanContext& context, ShaderModuleCache& shaders, VulkanPipelineCache& pipelines,
                        const Settings& settings, VulkanImage& array);
    /// Records the blur of each layer i for which `layers[i]` is non-zero; returns the texels written
    /// (two passes of resolution^2 per layer).
    double apply(VkCommandBuffer cmd, const std::vector<uint8_t>& layers) const;
    /// Taps each side of the centre; 0 = no blur.
    int radius() const { return mRadius; }

private:
    void release();
    void createTargets(VulkanContext& context, VulkanImage& array);
    void createDescriptors(VulkanContext& context, VulkanImage& array, const std::vector<float>& weights);
    void pass(VkCommandBuffer cmd, VkFramebuffer target, VkPipeline pipeline, size_t set, int layer) const;

    VkDevice mDevice = VK_NULL_HANDLE;
    Settings mSettings;
    int mRadius = 0;
    VulkanImage mIntermediate;
    VkRenderPass mPass = VK_NULL_HANDLE;
    VkFramebuffer mIntermediateFramebuffer = VK_NULL_HANDLE;
    std::vector<VkFramebuffer> mLayerFramebuffers;
    VkSampler mSampler = VK_NULL_HANDLE;
    VulkanBuffer mBlock; ///< blur.frag's BlurBlock
    static constexpr size_t kHorizontalSet = 0, kVerticalSet = 1;
    DescriptorSets mSets;
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    VkPipeline mHorizontal = VK_NULL_HANDLE, mVertical = VK_NULL_HANDLE;
};

} // namespace sb
