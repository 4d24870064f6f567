#pragma once
// A 2D (array or cube) VkImage with its own device-local memory and one view over all its layers.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

namespace sb {

class VulkanContext;

struct VulkanImageDesc {
    uint32_t width = 1, height = 1, layers = 1;
    VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
    VkImageUsageFlags usage = 0;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
    VkImageViewType viewType = VK_IMAGE_VIEW_TYPE_2D; ///< 2D_ARRAY for maps with a layer per light, CUBE
    bool cube = false;                                ///< CUBE_COMPATIBLE (layers a multiple of 6)
};

class VulkanImage {
public:
    VulkanImage() = default;
    VulkanImage(VulkanContext& context, const VulkanImageDesc& desc);
    ~VulkanImage();
    VulkanImage(VulkanImage&& other) noexcept;
    VulkanImage& operator=(VulkanImage&& other) noexcept;
    VulkanImage(const VulkanImage&) = delete;
    VulkanImage& operator=(const VulkanImage&) = delete;

    VkImage image() const { return mImage; }
    VkImageView view() const { return mView; } ///< all layers, the descriptor's view type
    /// A 2D view of one layer (created on first use, kept): what a framebuffer attaches per light.
    VkImageView layerView(uint32_t layer);
    const VulkanImageDesc& desc() const { return mDesc; }

private:
    void release();
    VkDevice mDevice = VK_NULL_HANDLE;
    VkImage mImage = VK_NULL_HANDLE;
    VkDeviceMemory mMemory = VK_NULL_HANDLE;
    VkImageView mView = VK_NULL_HANDLE;
    std::vector<VkImageView> mLayerViews; ///< desc.layers entries, VK_NULL_HANDLE until asked for
    VulkanImageDesc mDesc;
};

/// Records an image memory barrier moving all layers of `image` (aspect `aspect`) from `from` to `to`,
/// with the stage and access masks these layouts imply (undefined, colour/depth attachment, shader read,
/// transfer source/destination).
void transitionImage(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                     VkImageLayout to, uint32_t layers = 1);

} // namespace sb
