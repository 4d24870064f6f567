#include "techniques/shadowmap/DepthRangeVulkan.h"

#include <cstring>

#include "techniques/ViewDepth.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/LayerPasses.h"

namespace sb {

namespace {
constexpr uint32_t kGroupSide = 16;               // depth_range.comp's local size in x and y
constexpr uint32_t kClear[2] = {0x7f800000u, 0u}; // +inf bits and 0: nothing covered yet
} // namespace

DepthRangeVulkan::~DepthRangeVulkan() {
    release();
}

void DepthRangeVulkan::release() {
    if (!mDevice) return;
    vkDestroyPipeline(mDevice, mPipeline, nullptr);
    vkDestroyPipelineLayout(mDevice, mLayout, nullptr);
    vkDestroySampler(mDevice, mSampler, nullptr);
    mPipeline = VK_NULL_HANDLE;
    mLayout = VK_NULL_HANDLE;
    mSampler = VK_NULL_HANDLE;
    mSets = DescriptorSets();
    mBuffers = {};
    mDevice = VK_NULL_HANDLE;
}

void DepthRangeVulkan::compile(const VulkanCompileContext& ctx, const ViewDepthVulkan& depth) {
    release();
    mContext = &ctx.context;
    mDevice = ctx.context.device();
    mFrames = 0;
    LayerPasses::Sampling nearest;
    nearest.filter = VK_FILTER_NEAREST;
    mSampler = LayerPasses::sampler(mDevice, nearest, "depth range");
    using D = DescriptorSets;
    const D::Bindings bindings = {
        D::binding(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_COMPUTE_BIT),
        D::binding(1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT)};
    mSets = DescriptorSets(mDevice, {bindings, bindings}, "depth range");
    for (size_t i = 0; i < 2; ++i) {
        mBuffers[i] = VulkanBuffer(ctx.context, sizeof kClear, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        std::memcpy(mBuffers[i].map(), kClear, sizeof kClear);
        mSets.writeImage(i, 0, mSampler, depth.view(), VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
        mSets.writeBuffer(i, 1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mBuffers[i].buffer(), sizeof kClear);
    }
    const VkDescriptorSetLayout setLayout = mSets.layout(0);
    VkPipelineLayoutCreateInfo layout{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout.setLayoutCount = 1;
    layout.pSetLayouts = &setLayout;
    VulkanContext::check(vkCreatePipelineLayout(mDevice, &layout, nullptr, &mLayout),
                         "vkCreatePipelineLayout (depth range)");
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = ctx.shaders.get("shadowmap/depth_range.comp", {}, ShaderStage::Compute);
    info.stage.pName = "main";
    info.layout = mLayout;
    VulkanContext::check(vkCreateComputePipelines(mDevice, VK_NULL_HANDLE, 1, &info, nullptr, &mPipeline),
                         "vkCreateComputePipelines (depth range)");
}

void DepthRangeVulkan::record(VkCommandBuffer cmd, const ViewDepthVulkan& depth, size_t buffer) {
    // The buffer's last reduction (two frames ago) has finished: cleared from the host, seen at submit.
    std::memcpy(mBuffers[buffer].map(), kClear, sizeof kClear);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mPipeline);
    const VkDescriptorSet set = mSets.set(buffer);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, mLayout, 0, 1, &set, 0, nullptr);
    vkCmdDispatch(cmd, (depth.width() + kGroupSide - 1) / kGroupSide,
                  (depth.height() + kGroupSide - 1) / kGroupSide, 1);
    // The answer, to the host that reads it after the fence.
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost,
                         0, nullptr, 0, nullptr);
}

glm::vec2 DepthRangeVulkan::readWindow(size_t buffer) const {
    float window[2];
    std::memcpy(window, mBuffers[buffer].map(), sizeof window);
    return {window[0], window[1]};
}

glm::vec2 DepthRangeVulkan::latestWindowRange() const {
    if (mFrames == 0) return {1.0f, 0.0f};
    return readWindow(size_t((mFrames - 1) % 2));
}

glm::vec2 DepthRangeVulkan::run(const VulkanFrameContext& ctx, ViewDepthVulkan& depth) {
    const size_t current = size_t(mFrames % 2), previous = 1 - current;
    if (mFrames == 0) {
        mContext->submitNow([&](VkCommandBuffer cmd) {
            depth.record(ctx, cmd);
            record(cmd, depth, current);
        });
    } else {
        depth.record(ctx, ctx.cmd);
        record(ctx.cmd, depth, current);
    }
    mProj[current] = depth.proj();
    const size_t answer = mFrames == 0 ? current : previous;
    ++mFrames;
    mWindow = readWindow(answer);
    if (mWindow.x > mWindow.y) return mWindow; // nothing covered: an empty interval
    return ViewDepth::viewDepths(mWindow, mProj[answer]);
}

} // namespace sb
