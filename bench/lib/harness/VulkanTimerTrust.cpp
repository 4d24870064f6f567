#include "bench/lib/harness/VulkanTimerTrust.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "techniques/vulkan/VulkanSubmitter.h"
#include "vk/GraphicsPipeline.h"
#include "vk/ShaderModuleCache.h"
#include "vk/TimestampRing.h"
#include "vk/VulkanContext.h"
#include "vk/VulkanTargets.h"

namespace sb {

namespace {
using Clock = std::chrono::steady_clock;
/// What one calibration needs: the fill pipeline against both targets' render passes, a ring, a
/// command buffer and a fence.
class Fill final : public TimedFill {
public:
    Fill(VulkanContext& context, ShaderModuleCache& shaders)
        : mContext(context), mSmall(context, TimerTrust::kSmall, TimerTrust::kSmall),
          mLarge(context, TimerTrust::kLarge, TimerTrust::kLarge), mRing(context, 1, 2) {
        mSmall.setVisibilityOutput(false);
        mLarge.setVisibilityOutput(false);
        mLayout = createPipelineLayout(context, {}, sizeof(VulkanPush));
        GraphicsPipelineDesc d;
        const ShaderModules modules =
            shaders.get(ShaderSources{"common/fullscreen.vert", "calibrate/fill.frag", ""}, {});
        d.vertex = modules.vertex;
        d.fragment = modules.fragment;
        d.depthTest = d.depthWrite = false;
        d.layout = mLayout;
        d.renderPass = mSmall.renderPass(false); // the same formats: compatible with the large one's
        d.colourAttachments = 1;
        mPipeline = createGraphicsPipeline(context, d);
        VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
        alloc.commandPool = context.commandPool();
        alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        alloc.commandBufferCount = 1;
        VulkanContext::check(vkAllocateCommandBuffers(context.device(), &alloc, &mCmd),
                             "vkAllocateCommandBuffers");
        VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VulkanContext::check(vkCreateFence(context.device(), &fence, nullptr, &mFence), "vkCreateFence");
    }
    ~Fill() {
        VkDevice d = mContext.device();
        vkDeviceWaitIdle(d);
        vkDestroyFence(d, mFence, nullptr);
        vkFreeCommandBuffers(d, mContext.commandPool(), 1, &mCmd);
        vkDestroyPipeline(d, mPipeline, nullptr);
        vkDestroyPipelineLayout(d, mLayout, nullptr);
    }
    Fill(const Fill&) = delete;
    Fill& operator=(const Fill&) = delete;

    /// One frame as the harness times one: clear, the fill pass, submit, fence.
    Timing draw(bool large, int iterations) override {
        VulkanTargets& t = large ? mLarge : mSmall;
        const auto t0 = Clock::now();
        vkResetCommandBuffer(mCmd, 0);
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        vkBeginCommandBuffer(mCmd, &begin);
        mRing.beginFrame(mCmd, mFrame++);
        t.recordClear(mCmd, 0.0f, 0.0f, 0.0f);
        mRing.pass(mCmd, "calibrate/fill");
        t.beginPass(mCmd);
        vkCmdBindPipeline(mCmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline);
        VulkanPush push;
        push.ints.x = iterations;
        vkCmdPushConstants(mCmd, mLayout, kPushStages, 0, sizeof push, &push);
        vkCmdDraw(mCmd, 3, 1, 0, 0);
        vkCmdEndRenderPass(mCmd);
        mRing.endFrame(mCmd);
        vkEndCommandBuffer(mCmd);
        mContext.submit(mCmd, mFence);
        vkWaitForFences(mContext.device(), 1, &mFence, VK_TRUE, UINT64_MAX);
        const double wall = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        vkResetFences(mContext.device(), 1, &mFence);
        const std::vector<PassTimes> frames = mRing.collect();
        return {wall, frames.empty() ? 0.0 : frames.back().totalMs};
    }

private:
    VulkanContext& mContext;
    VulkanTargets mSmall, mLarge;
    TimestampRing mRing;
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    VkPipeline mPipeline = VK_NULL_HANDLE;
    VkCommandBuffer mCmd = VK_NULL_HANDLE;
    VkFence mFence = VK_NULL_HANDLE;
    uint64_t mFrame = 0;
};

} // namespace

TimerVerdict VulkanTimerTrust::calibrate(VulkanContext& context, ShaderModuleCache& shaders) {
    const auto t0 = Clock::now();
    if (context.timestampPeriodNs() <= 0.0) {
        TimerVerdict v;
        v.checked = true;
        v.reason = "the device's graphics queue writes no timestamps (timestampValidBits 0)";
        return v;
    }
    Fill fill(context, shaders);
    TimerVerdict v = TimerTrust::calibrateWith(fill, "vkCmdWriteTimestamp pairs");
    v.calibrationMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    return v;
}

} // namespace sb
