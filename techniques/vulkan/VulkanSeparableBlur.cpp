#include "techniques/vulkan/VulkanSeparableBlur.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "techniques/GaussianKernel.h"
#include "techniques/vulkan/VulkanPipelineCache.h"
#include "vk/GraphicsPipeline.h"
#include "vk/LayerPasses.h"
#include "vk/ShaderModuleCache.h"
#include "vk/VulkanContext.h"

namespace sb {

VulkanSeparableBlur::~VulkanSeparableBlur() {
    release();
}

void VulkanSeparableBlur::release() {
    if (!mDevice) return;
    if (mIntermediateFramebuffer) vkDestroyFramebuffer(mDevice, mIntermediateFramebuffer, nullptr);
    for (VkFramebuffer f : mLayerFramebuffers) vkDestroyFramebuffer(mDevice, f, nullptr);
    mLayerFramebuffers.clear();
    vkDestroyRenderPass(mDevice, mPass, nullptr);
    vkDestroySampler(mDevice, mSampler, nullptr);
    vkDestroyPipelineLayout(mDevice, mLayout, nullptr);
    mIntermediateFramebuffer = VK_NULL_HANDLE;
    mPass = VK_NULL_HANDLE;
    mSampler = VK_NULL_HANDLE;
    mLayout = VK_NULL_HANDLE;
    mHorizontal = mVertical = VK_NULL_HANDLE; // owned by the pipeline cache
    mSets = DescriptorSets();
    mBlock = VulkanBuffer();
    mIntermediate = VulkanImage();
}

void VulkanSeparableBlur::createTargets(VulkanContext& context, VulkanImage& array) {
    const uint32_t size = uint32_t(mSettings.resolution);
    VulkanImageDesc d;
    d.width = d.height = size;
    d.format = mSettings.format;
    d.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    mIntermediate = VulkanImage(context, d);
    // Each pass overwrites its target whole: its old contents are not loaded.
    mPass = LayerPasses::colourPass(mDevice, mSettings.format, VK_ATTACHMENT_LOAD_OP_DONT_CARE, "blur");
    const VkImageView intermediate = mIntermediate.view();
    mIntermediateFramebuffer =
        LayerPasses::framebuffer(mDevice, mPass, {&intermediate, 1}, {size, size}, 1, "blur");
    mLayerFramebuffers = LayerPasses::layerFramebuffers(mDevice, mPass, array, array.desc().layers, "blur");
}

void VulkanSeparableBlur::createDescriptors(VulkanContext& context, VulkanImage& array,
                                            const std::vector<float>& weights) {
    // Both passes read with texelFetch: the sampler's filter is never used.
    LayerPasses::Sampling nearest;
    nearest.filter = VK_FILTER_NEAREST;
    mSampler = LayerPasses::sampler(mDevice, nearest, "blur");
    using D = DescriptorSets;
    const D::Bindings bindings = {
        D::binding(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT),
        D::binding(1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT)};
    mSets = DescriptorSets(mDevice, {bindings, bindings}, "blur");
    // BlurBlock (std140): uExponent at 0, uWeights[k] at 16 + 16 k.
    const VkDeviceSize size = 16 + 16 * weights.size();
    mBlock = VulkanBuffer(context, size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    char* base = static_cast<char*>(mBlock.map());
    std::memset(base, 0, size);
    std::memcpy(base, &mSettings.exponent, sizeof(float));
    for (size_t k = 0; k < weights.size(); ++k) std::memcpy(base + 16 + 16 * k, &weights[k], sizeof(float));
    const VkImageLayout read = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    mSets.writeImage(kHorizontalSet, 0, mSampler, array.view(), read);
    mSets.writeImage(kVerticalSet, 0, mSampler, mIntermediate.view(), read);
    for (size_t set : {kHorizontalSet, kVerticalSet})
        mSets.writeBuffer(set, 1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, mBlock.buffer(), size);
}

std::string VulkanSeparableBlur::compile(VulkanContext& context, ShaderModuleCache& shaders,
                                         VulkanPipelineCache& pipelines, const Settings& settings,
                                         VulkanImage& array) {
    release();
    mDevice = context.device();
    mSettings = settings;
    if (settings.pointSampled && settings.logSpace)
        throw std::invalid_argument(
            "VulkanSeparableBlur: the log-space mode takes the texel-integral kernel");
    // The point-sampled kernel's weights are the shader's; the block still holds BLUR_RADIUS + 1 (unread).
    const std::vector<float> weights = settings.pointSampled
                                           ? std::vector<float>(size_t(std::max(0, settings.width)) + 1, 0.0f)
                                           : GaussianKernel::texelIntegral(settings.width);
    mRadius = int(weights.size()) - 1;
    if (mRadius == 0) return "";
    createTargets(context, array);
    createDescriptors(context, array, weights);
    mLayout = createPipelineLayout(context, {mSets.layout(kHorizontalSet)}, sizeof(int32_t));

    // As SeparableBlur's defines: the texel-integral kernel and clamp to edge are the shader's defaults.
    Defines defines = {{"BLUR_RADIUS", std::to_string(mRadius)}};
    if (settings.pointSampled) defines["BLUR_POINT_SAMPLED"] = "";
    if (settings.outsideOne) defines["BLUR_OUTSIDE_ONE"] = "";
    if (settings.logSpace) defines["LOG_SPACE"] = "";
    auto pipeline = [&](const Defines& d) {
        const ShaderModules modules =
            shaders.get(ShaderSources{"common/fullscreen.vert", "common/blur.frag", ""}, d);
        GraphicsPipelineDesc desc;
        desc.vertex = modules.vertex;
        desc.fragment = modules.fragment;
        desc.depthTest = desc.depthWrite = false;
        desc.renderPass = mPass;
        desc.layout = mLayout;
        const std::string key = "blur|format=" + std::to_string(int(settings.format)) + "|" + definesKey(d);
        return std::make_pair(pipelines.get(key, desc), definesKey(d));
    };
    const auto vertical = pipeline(defines);
    defines["BLUR_FROM_ARRAY"] = "";
    const auto horizontal = pipeline(defines);
    mVertical = vertical.first;
    mHorizontal = horizontal.first;
    return horizontal.second + "|" + vertical.second;
}

void VulkanSeparableBlur::pass(VkCommandBuffer cmd, VkFramebuffer target, VkPipeline pipeline, size_t set,
                               int layer) const {
    const uint32_t size = uint32_t(mSettings.resolution);
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = mPass;
    begin.framebuffer = target;
    begin.renderArea.extent = {size, size};
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    const VkViewport viewport{0.0f, 0.0f, float(size), float(size), 0.0f, 1.0f};
    const VkRect2D scissor{{0, 0}, {size, size}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    const VkDescriptorSet s = mSets.set(set);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, 0, 1, &s, 0, nullptr);
    const int32_t value = layer;
    vkCmdPushConstants(cmd, mLayout, kPushConstantStages, 0, sizeof value, &value);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRenderPass(cmd);
}

double VulkanSeparableBlur::apply(VkCommandBuffer cmd, const std::vector<uint8_t>& layers) const {
    if (mRadius == 0) return 0.0;
    double texels = 0.0;
    for (size_t i = 0; i < layers.size() && i < mLayerFramebuffers.size(); ++i) {
        if (!layers[i]) continue; // a constant layer (no caster) is its own blur
        pass(cmd, mIntermediateFramebuffer, mHorizontal, kHorizontalSet, int(i));
        pass(cmd, mLayerFramebuffers[i], mVertical, kVerticalSet, -1);
        texels += 2.0 * double(mSettings.resolution) * mSettings.resolution;
    }
    return texels;
}

} // namespace sb
