#include "vk/TimestampRing.h"

#include <algorithm>

#include "core/Error.h"
#include "vk/VulkanContext.h"

namespace sb {

TimestampRing::TimestampRing(VulkanContext& context, uint32_t frames, uint32_t passesPerFrame)
    : mContext(context), mFrames(std::max(frames, 1u)), mPerFrame(std::max(passesPerFrame, 1u)),
      mSlots(mFrames) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(context.physicalDevice(), &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(context.physicalDevice(), &count, families.data());
    const uint32_t bits =
        context.queueFamily() < count ? families[context.queueFamily()].timestampValidBits : 0;
    mMask = bits >= 64 ? ~0ull : bits == 0 ? 0ull : (1ull << bits) - 1;

    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = mFrames * (mPerFrame + 1);
    VulkanContext::check(vkCreateQueryPool(context.device(), &info, nullptr, &mPool), "vkCreateQueryPool");
}

TimestampRing::~TimestampRing() {
    if (mPool) vkDestroyQueryPool(mContext.device(), mPool, nullptr);
}

void TimestampRing::beginFrame(VkCommandBuffer cmd, uint64_t frame) {
    mCurrent = (mCurrent + 1) % mFrames;
    Slot& slot = mSlots[mCurrent];
    slot.frame = frame;
    slot.names.clear();
    slot.stamps = 0;
    slot.pending = false; // an uncollected frame in this slot is dropped
    const uint32_t first = mCurrent * (mPerFrame + 1);
    vkCmdResetQueryPool(cmd, mPool, first, mPerFrame + 1);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, mPool, first);
    mWritten = 1;
}

void TimestampRing::pass(VkCommandBuffer cmd, const std::string& name) {
    if (mWritten == 0)
        throw Error("vulkan: TimestampRing::pass('" + name + "') before beginFrame", ExitCode::Failure);
    Slot& slot = mSlots[mCurrent];
    if (slot.names.size() >= mPerFrame) return; // no room: the last pass that fitted runs on
    if (!slot.names.empty()) {
        // Ends pass names.size() - 1, begins this one: timestamp names.size().
        vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, mPool,
                            mCurrent * (mPerFrame + 1) + mWritten);
        ++mWritten;
    }
    slot.names.push_back(name);
}

void TimestampRing::endFrame(VkCommandBuffer cmd) {
    if (mWritten == 0) return;
    Slot& slot = mSlots[mCurrent];
    // mWritten <= mPerFrame here (one per pass begun, the first pass's being the frame's first), so the
    // last timestamp stays inside the slot.
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, mPool,
                        mCurrent * (mPerFrame + 1) + mWritten);
    slot.stamps = mWritten + 1;
    slot.pending = true;
    mWritten = 0;
}

std::vector<PassTimes> TimestampRing::collect() {
    std::vector<Slot*> pending;
    for (Slot& slot : mSlots)
        if (slot.pending) pending.push_back(&slot);
    std::sort(pending.begin(), pending.end(),
              [](const Slot* a, const Slot* b) { return a->frame < b->frame; });

    const double msPerTick = mContext.timestampPeriodNs() * 1e-6;
    std::vector<PassTimes> out;
    std::vector<uint64_t> ticks;
    for (Slot* slot : pending) {
        const uint32_t first = static_cast<uint32_t>(slot - mSlots.data()) * (mPerFrame + 1);
        ticks.assign(slot->stamps, 0);
        VkResult result = vkGetQueryPoolResults(mContext.device(), mPool, first, slot->stamps,
                                                ticks.size() * sizeof(uint64_t), ticks.data(),
                                                sizeof(uint64_t), VK_QUERY_RESULT_64_BIT);
        if (result == VK_NOT_READY) continue; // next collect
        VulkanContext::check(result, "vkGetQueryPoolResults");
        auto elapsed = [&](uint32_t a, uint32_t b) {
            return double((ticks[b] - ticks[a]) & mMask) * msPerTick;
        };
        PassTimes times;
        times.frame = slot->frame;
        // With no pass named, the frame is one span (stamps == 2).
        for (size_t k = 0; k < slot->names.size(); ++k)
            times.passMs.emplace_back(slot->names[k], elapsed(uint32_t(k), uint32_t(k + 1)));
        times.totalMs = elapsed(0, slot->stamps - 1);
        slot->pending = false;
        out.push_back(std::move(times));
    }
    return out;
}

} // namespace sb
