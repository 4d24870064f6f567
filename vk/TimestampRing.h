#pragma once
// Per-pass GPU times on Vulkan (docs/ARCHITECTURE.md, "The timing contract"), the analogue of
// gl/TimerQueryRing: each frame owns a slot of a timestamp query pool, vkCmdWriteTimestamp at the
// top of the frame and at the end of every pass (bottom of pipe), and the values are read back frames
// later (VK_QUERY_RESULT_64_BIT without WAIT: a slot not yet available is left for the next collect), so
// reading never stalls the loop. Whether these numbers measure the frame is the trust check's question,
// not this class's.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "core/PassTimes.h"

namespace sb {

class VulkanContext;

/// One frame's pass times in milliseconds, in the order the passes began (a pass may repeat).

class TimestampRing {
public:
    /// `frames` slots of up to `passesPerFrame` passes each.
    TimestampRing(VulkanContext& context, uint32_t frames, uint32_t passesPerFrame);
    ~TimestampRing();
    TimestampRing(const TimestampRing&) = delete;
    TimestampRing& operator=(const TimestampRing&) = delete;

    /// Resets the next slot (vkCmdResetQueryPool, outside a render pass) and writes the frame's first
    /// timestamp. A slot whose values were never collected is dropped (its frame counts as missing).
    void beginFrame(VkCommandBuffer cmd, uint64_t frame);
    /// Ends the previous pass (if any) and begins `name`: one timestamp (bottom of pipe), except for the
    /// frame's first pass, which the frame's first timestamp begins. Outside a render pass or inside.
    /// Passes beyond `passesPerFrame` write nothing: their time counts in the last pass that fitted.
    void pass(VkCommandBuffer cmd, const std::string& name);
    /// Ends the last pass of the frame.
    void endFrame(VkCommandBuffer cmd);
    /// Frames whose timestamps are available, oldest first; never waits.
    std::vector<PassTimes> collect();

private:
    struct Slot {
        uint64_t frame = 0;
        std::vector<std::string> names; ///< pass k spans timestamps k .. k+1
        uint32_t stamps = 0;            ///< timestamps written (endFrame's included)
        bool pending = false;
    };
    VulkanContext& mContext;
    VkQueryPool mPool = VK_NULL_HANDLE;
    uint32_t mFrames, mPerFrame;
    std::vector<Slot> mSlots;
    uint32_t mCurrent = 0;
    uint32_t mWritten = 0; ///< timestamps written in the current slot
    uint64_t mMask = ~0ull;
};

} // namespace sb
