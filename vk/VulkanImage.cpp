#include "vk/VulkanImage.h"

#include <utility>

#include "core/Error.h"
#include "vk/VulkanContext.h"

namespace sb {
namespace {

VkImageView createView(VkDevice device, VkImage image, const VulkanImageDesc& desc, VkImageViewType type,
                       uint32_t firstLayer, uint32_t layers) {
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image;
    info.viewType = type;
    info.format = desc.format;
    info.subresourceRange = {desc.aspect, 0, 1, firstLayer, layers};
    VkImageView view = VK_NULL_HANDLE;
    VulkanContext::check(vkCreateImageView(device, &info, nullptr, &view), "vkCreateImageView");
    return view;
}

/// What a layout's users do to the image (access) and in which stages, as the source or destination of a
/// barrier.
struct LayoutUse {
    VkAccessFlags access;
    VkPipelineStageFlags stages;
};

LayoutUse layoutUse(VkImageLayout layout, bool source) {
    constexpr VkPipelineStageFlags kDepthStages =
        VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    constexpr VkPipelineStageFlags kShaderStages = VK_PIPELINE_STAGE_VERTEX_SHADER_BIT |
                                                   VK_PIPELINE_STAGE_GEOMETRY_SHADER_BIT |
                                                   VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    switch (layout) {
    case VK_IMAGE_LAYOUT_UNDEFINED:
    case VK_IMAGE_LAYOUT_PREINITIALIZED:
        return {0, source ? VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT : VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT};
    case VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL:
        return {VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT};
    case VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL:
        return {VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                kDepthStages};
    case VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL:
        return {VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_SHADER_READ_BIT,
                kDepthStages | kShaderStages};
    case VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL:
        return {VK_ACCESS_SHADER_READ_BIT, kShaderStages};
    case VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL:
        return {VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT};
    case VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL:
        return {VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT};
    default: // GENERAL and anything else: everything
        return {VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT};
    }
}

} // namespace

VulkanImage::VulkanImage(VulkanContext& context, const VulkanImageDesc& desc)
    : mDevice(context.device()), mDesc(desc) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.flags = desc.cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = desc.format;
    info.extent = {desc.width, desc.height, 1};
    info.mipLevels = 1;
    info.arrayLayers = desc.layers;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = desc.usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VulkanContext::check(vkCreateImage(mDevice, &info, nullptr, &mImage), "vkCreateImage");
    try {
        VkMemoryRequirements req{};
        vkGetImageMemoryRequirements(mDevice, mImage, &req);
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.allocationSize = req.size;
        alloc.memoryTypeIndex = context.memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        VulkanContext::check(vkAllocateMemory(mDevice, &alloc, nullptr, &mMemory), "vkAllocateMemory");
        VulkanContext::check(vkBindImageMemory(mDevice, mImage, mMemory, 0), "vkBindImageMemory");
        mView = createView(mDevice, mImage, mDesc, desc.viewType, 0, desc.layers);
        mLayerViews.assign(desc.layers, VK_NULL_HANDLE);
    } catch (...) {
        release();
        throw;
    }
}

VkImageView VulkanImage::layerView(uint32_t layer) {
    if (layer >= mLayerViews.size())
        throw Error("vulkan: image layer " + std::to_string(layer) + " out of range (" +
                        std::to_string(mLayerViews.size()) + " layers)",
                    ExitCode::Failure);
    if (!mLayerViews[layer])
        mLayerViews[layer] = createView(mDevice, mImage, mDesc, VK_IMAGE_VIEW_TYPE_2D, layer, 1);
    return mLayerViews[layer];
}

VulkanImage::~VulkanImage() {
    release();
}

void VulkanImage::release() {
    if (mDevice) {
        for (VkImageView view : mLayerViews)
            if (view) vkDestroyImageView(mDevice, view, nullptr);
        if (mView) vkDestroyImageView(mDevice, mView, nullptr);
        if (mImage) vkDestroyImage(mDevice, mImage, nullptr);
        if (mMemory) vkFreeMemory(mDevice, mMemory, nullptr);
    }
    mLayerViews.clear();
    mDevice = VK_NULL_HANDLE;
    mView = VK_NULL_HANDLE;
    mImage = VK_NULL_HANDLE;
    mMemory = VK_NULL_HANDLE;
}

VulkanImage::VulkanImage(VulkanImage&& other) noexcept
    : mDevice(std::exchange(other.mDevice, VK_NULL_HANDLE)),
      mImage(std::exchange(other.mImage, VK_NULL_HANDLE)),
      mMemory(std::exchange(other.mMemory, VK_NULL_HANDLE)),
      mView(std::exchange(other.mView, VK_NULL_HANDLE)), mLayerViews(std::move(other.mLayerViews)),
      mDesc(other.mDesc) {
    other.mLayerViews.clear();
}

VulkanImage& VulkanImage::operator=(VulkanImage&& other) noexcept {
    if (this != &other) {
        release();
        mDevice = std::exchange(other.mDevice, VK_NULL_HANDLE);
        mImage = std::exchange(other.mImage, VK_NULL_HANDLE);
        mMemory = std::exchange(other.mMemory, VK_NULL_HANDLE);
        mView = std::exchange(other.mView, VK_NULL_HANDLE);
        mLayerViews = std::move(other.mLayerViews);
        other.mLayerViews.clear();
        mDesc = other.mDesc;
    }
    return *this;
}

void transitionImage(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from,
                     VkImageLayout to, uint32_t layers) {
    LayoutUse src = layoutUse(from, true);
    LayoutUse dst = layoutUse(to, false);
    if (to == VK_IMAGE_LAYOUT_UNDEFINED) dst = {0, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT};
    VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    barrier.srcAccessMask =
        src.access & ~VkAccessFlags(VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT);
    barrier.dstAccessMask = dst.access;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {aspect, 0, VK_REMAINING_MIP_LEVELS, 0, layers};
    vkCmdPipelineBarrier(cmd, src.stages, dst.stages, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

} // namespace sb
