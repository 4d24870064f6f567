#include "techniques/vulkan/VulkanDepthMapSet.h"

#include <utility>

#include "techniques/PropertySet.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/vulkan/VulkanDepthMaps.h"
#include "vk/VulkanContext.h"

namespace sb {

VulkanDepthMapSet::VulkanDepthMapSet(VulkanContext& context, uint32_t size, uint32_t layers, uint32_t drawn,
                                     bool cube)
    : mDevice(context.device()), mSize(size), mLayers(layers),
      mFormat(VulkanDepthMaps::format(context.physicalDevice())) {
    mImage = VulkanDepthMaps::image(context, mFormat, size, layers, cube);
    mPass = VulkanDepthMaps::renderPass(mDevice, mFormat);
    mFramebuffers = LayerPasses::layerFramebuffers(mDevice, mPass, mImage, drawn, "shadow map");
}

VulkanDepthMapSet::~VulkanDepthMapSet() {
    release();
}

VulkanDepthMapSet::VulkanDepthMapSet(VulkanDepthMapSet&& other) noexcept {
    *this = std::move(other);
}

VulkanDepthMapSet& VulkanDepthMapSet::operator=(VulkanDepthMapSet&& other) noexcept {
    if (this == &other) return *this;
    release();
    mDevice = std::exchange(other.mDevice, VK_NULL_HANDLE);
    mSize = other.mSize;
    mLayers = other.mLayers;
    mFormat = other.mFormat;
    mImage = std::move(other.mImage);
    mPass = std::exchange(other.mPass, VK_NULL_HANDLE);
    mFramebuffers = std::exchange(other.mFramebuffers, {});
    mLayersView = std::exchange(other.mLayersView, VK_NULL_HANDLE);
    mSamplers = std::exchange(other.mSamplers, {});
    mSlots = std::move(other.mSlots);
    return *this;
}

void VulkanDepthMapSet::release() {
    if (!mDevice) return;
    for (VkFramebuffer f : mFramebuffers) vkDestroyFramebuffer(mDevice, f, nullptr);
    for (VkSampler s : mSamplers) vkDestroySampler(mDevice, s, nullptr);
    vkDestroyImageView(mDevice, mLayersView, nullptr);
    vkDestroyRenderPass(mDevice, mPass, nullptr);
    mFramebuffers.clear();
    mSamplers.clear();
    mLayersView = VK_NULL_HANDLE;
    mPass = VK_NULL_HANDLE;
    mSlots = UniformSlots();
    mImage = VulkanImage();
    mDevice = VK_NULL_HANDLE;
}

size_t VulkanDepthMapSet::addLayeredFramebuffer() {
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = mImage.image();
    info.viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    info.format = mFormat;
    info.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, mLayers};
    VulkanContext::check(vkCreateImageView(mDevice, &info, nullptr, &mLayersView),
                         "vkCreateImageView (depth map layers)");
    mFramebuffers.push_back(
        LayerPasses::framebuffer(mDevice, mPass, {&mLayersView, 1}, {mSize, mSize}, mLayers, "shadow map"));
    return mFramebuffers.size() - 1;
}

VkSampler VulkanDepthMapSet::addSampler(const LayerPasses::Sampling& sampling, const char* what) {
    mSamplers.push_back(LayerPasses::sampler(mDevice, sampling, what));
    return mSamplers.back();
}

VkSampler VulkanDepthMapSet::addSampler(bool compare) {
    mSamplers.push_back(VulkanDepthMaps::sampler(mDevice, compare));
    return mSamplers.back();
}

void VulkanDepthMapSet::createSlots(VulkanContext& context, VkDeviceSize bytes, uint32_t count) {
    mSlots = UniformSlots(context, bytes, count);
}

void VulkanDepthMapSet::depthPipeline(GraphicsPipelineDesc& desc, double biasSlope,
                                      double biasConstant) const {
    desc.depthBias = true;
    desc.depthBiasSlope = float(biasSlope);
    desc.depthBiasConstant = float(biasConstant);
    desc.colourAttachments = 0;
    desc.renderPass = mPass;
}

void VulkanDepthMapSet::depthPipeline(GraphicsPipelineDesc& desc, const PropertySet& properties) const {
    depthPipeline(desc, properties.getFloat(ShadowMapProperties::kBiasSlope),
                  properties.getFloat(ShadowMapProperties::kBiasConstant));
}

std::string VulkanDepthMapSet::biasKey(double biasSlope, double biasConstant) {
    return "|bias=" + std::to_string(biasSlope) + "," + std::to_string(biasConstant) + "|";
}

std::string VulkanDepthMapSet::biasKey(const PropertySet& properties) {
    return biasKey(properties.getFloat(ShadowMapProperties::kBiasSlope),
                   properties.getFloat(ShadowMapProperties::kBiasConstant));
}

void VulkanDepthMapSet::begin(VkCommandBuffer cmd, size_t index) const {
    LayerPasses::beginDepthPass(cmd, mPass, mFramebuffers[index], {mSize, mSize}, 1.0f);
}

} // namespace sb
